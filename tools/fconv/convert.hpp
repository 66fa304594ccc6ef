#pragma once
// The conversions of one kind each, called by convert_command once the input is read
// and the output format is known to be of the input's kind.

#include <string>

#include "commands.hpp"
#include "formats/input.hpp"

namespace fest::fconv_tool {

// Meshes: what fest or the output format cannot hold is refused (exit 3) unless
// o.drop_unrepresentable, then counted in a warning. Returns the output file's bytes.
std::string convert_mesh(const formats::Input& in, formats::Format to, const ConvertOptions& o);

// Volumes: o.frame picks one frame, o.volume_type/o.rescale convert values (warning with
// the count of values clipped to the type's range); writes o.output itself, because a
// .hdr/.img pair is two files.
void convert_volume(const formats::Input& in, const formats::OutputFormat& out, const ConvertOptions& o);

// A volume, VTK image data or frame stream drawn as a picture (o.view, o.slice, o.window,
// o.convention) and written in the image format `out`.
void volume_quick_look(const formats::Input& in, const formats::OutputFormat& out, const ConvertOptions& o);

}  // namespace fest::fconv_tool
