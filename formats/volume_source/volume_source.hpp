#pragma once
// One scalar volume from any of the inputs isosurf and volrender accept: NIfTI, NRRD,
// MetaImage (through formats/volume), VTK image data (.vti: a point array, vectors reduced
// to a component), and the fest frame stream (man/man5/fest-frame.5: concatenated
// attached NRRD frames from fluidsim, channel axis first, "# fest-frame: ... fields=" in
// the header), from which one frame and one field are taken; a 4-D volume (a time series)
// gives one frame the same way; a headerless raw volume is read with an explicit layout.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/volume.hpp"
#include "formats/input.hpp"

namespace fest::formats {

// The layout of a headerless volume: samples x fastest, then y, then z (docs/isosurf.md
// "Inputs").
struct RawLayout {
  std::array<std::size_t, 3> dims{0, 0, 0};
  ScalarType type = ScalarType::f32;
  bool big_endian = false;
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
};

// What a vector field becomes: its magnitude or one component (a scalar field is itself).
enum class VectorComponent { mag, x, y, z };

struct VolumeSourceOptions {
  std::string field;              // VTI point array / frame-stream field; "" = active scalars / first field
  VectorComponent component = VectorComponent::mag;
  long frame = -1;                // frame-stream / 4-D series frame (0-based); -1 = the last
  std::optional<RawLayout> raw;   // the bytes are a headerless volume of this layout
};

// "NX,NY,NZ,TYPE[,little|big]" (TYPE as scalar_type_name: uint8 ... float64) -> a layout
// with unit spacing; throws std::invalid_argument saying what is wrong.
RawLayout parse_raw_layout(std::string_view text);

// A headerless volume: the bytes must hold exactly dims[0]*dims[1]*dims[2] samples of the
// layout's type (else Status::bad_input "raw volume of ... needs N bytes, got M (where)").
Volume read_raw_volume(std::string_view bytes, const RawLayout& layout, const std::string& where);

// The input of read_volume_source: load_input(path), except that the bytes of raw input
// (options.raw) are taken as they are, neither recognised as a format nor gunzipped.
Input load_volume_input(const std::string& path, const VolumeSourceOptions& options);

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

// Every frame of an input, one at a time: the frames of a frame stream, of a 4-D volume
// (a time series), or the one frame of a 3-D volume. The input must outlive it.
class VolumeFrames {
 public:
  // Throws like read_volume_source (options.frame is ignored).
  VolumeFrames(const Input& in, const VolumeSourceOptions& options);
  std::size_t count() const noexcept { return count_; }
  // Frame t (0-based, < count()) as a 3-D volume.
  Volume frame(std::size_t t) const;

 private:
  VolumeSourceOptions options_;
  std::size_t count_ = 1;
  std::vector<StreamFrame> stream_;  // a frame stream's frames (views into the input)
  std::optional<Volume> series_;     // otherwise the parsed 4-D (or 3-D) volume
};

}  // namespace fest::formats
