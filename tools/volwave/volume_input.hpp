#pragma once
// Every volume fest reads, as one scalar Volume: NIfTI, NRRD, MetaImage (formats/volume),
// VTK image data (.vti, formats/dataset) and the frame streams of fluidsim and lbmsim
// (concatenated NRRD frames, lib/fluidsim/frame.hpp). Inputs holding several scalars
// (arrays, fields, components, frames) are refused unless `select` names one: nothing
// is dropped silently.

#include <string>

#include "commands.hpp"
#include "core/volume.hpp"

namespace fest::volwave_tool {

Volume read_any_volume(const std::string& path, const InputSelect& select);

// Writes a volume by the output path's extension or `to` (nrrd on standard output).
void write_any_volume(const Volume& v, const std::string& path, const std::string& to);

}  // namespace fest::volwave_tool
