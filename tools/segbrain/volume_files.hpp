#pragma once
// segbrain's volume inputs and outputs: any volume formats/ reads, 3-D; outputs in the
// format --to names, else the one of the path's extension (NIfTI on standard output).

#include <optional>
#include <string>

#include "core/volume.hpp"
#include "formats/detect.hpp"

namespace fest::segbrain_tool {

// `what` names the command in the message of a volume that is not 3-D.
Volume read_volume_input(const std::string& path, const char* what);
void write_volume_output(const Volume& v, const std::string& path, const std::optional<formats::OutputFormat>& to);

}  // namespace fest::segbrain_tool
