#pragma once
// One scalar volume from any of the inputs isosurf and volrender accept: NIfTI, NRRD,
// MetaImage (through formats/volume), VTK image data (.vti: a point array, vectors reduced
// to a component), and the fest frame stream (man/man5/fest-frame.5: concatenated
// attached NRRD frames from fluidsim, channel axis first, "# fest-frame: ... fields=" in
// the header), from which one frame and one field are taken.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/volume.hpp"
#include "formats/input.hpp"

namespace fest::formats {

struct VolumeSourceOptions {
  std::string field;              // VTI point array / frame-stream field; "" = active scalars / first field
  std::string component = "mag";  // vectors: mag | x | y | z
  long frame = -1;                // frame-stream frame (0-based); -1 = the last
};

// Throws Status::bad_input naming the input for anything unreadable; Status::usage for a
// field or frame that does not exist (the message lists what does).
Volume read_volume_source(const Input& in, const VolumeSourceOptions& options);

// True when the bytes start a fest frame stream.
bool is_frame_stream(std::string_view bytes) noexcept;

// A frame stream's frames, decoded: fields (name, components) and the channel-first data
// of one frame; exposed for the fuzz target and the tests.
struct StreamFrame {
  std::vector<std::pair<std::string, int>> fields;
  std::size_t size[3] = {1, 1, 1};
  double spacing[3] = {1, 1, 1};
  int dim = 3;
  std::string_view data;  // raw little-endian
  bool float64 = false;
};
// Splits and checks the headers of every frame; throws Status::bad_input ("truncated NRRD
// frame ...").
std::vector<StreamFrame> split_frame_stream(std::string_view bytes, const std::string& where);

}  // namespace fest::formats
