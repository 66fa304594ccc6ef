#pragma once
// The frame stream of fest (man/man5/fest-frame.5): a concatenation of complete attached
// NRRD files, one per frame, channel axis first, raw little-endian float32 (or float64),
// each with the header comment
//   # fest-frame: index=<f> time=<t> fields=density:1,velocity:3
// This file turns frames into bytes and back; it performs no I/O.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fluidsim/grid.hpp"

namespace fest::fluidsim {

struct FrameField {
  std::string name;
  int components = 1;
};

struct Frame {
  long index = 0;
  double time = 0.0;
  int dim = 3;
  std::array<int, 3> size{1, 1, 1};  // nodes per axis (wall nodes included)
  double spacing = 1.0;
  std::vector<FrameField> fields;
  std::vector<double> data;  // channel fastest, then x, y, z
  bool float64 = false;      // stored type

  int channels() const noexcept;
  std::size_t nodes() const noexcept { return static_cast<std::size_t>(size[0]) * size[1] * size[2]; }
  // First channel of a field, or -1.
  int channel_of(const std::string& name) const noexcept;
  // One component of a field as a node array (x fastest).
  std::vector<double> component(int channel) const;
  // A field's magnitude (its only component for scalars).
  std::vector<double> magnitude(const std::string& name) const;
};

std::string encode_frame(const Frame& frame);

// Decodes the frame that starts at `offset`; returns the offset after it. Throws
// Status::bad_input: "truncated NRRD frame: expected N bytes, got M (where, frame f)".
std::size_t decode_frame(std::string_view bytes, std::size_t offset, Frame& out, const std::string& where,
                         long frame_number);

// A frame of the selected fields: "velocity" (3 components, 0 beyond 2-D) or scalar names.
struct State;
Frame make_frame(const Layout& layout, const State& state, const std::vector<std::string>& scalar_names,
                 const std::vector<std::string>& fields, long index, double time);

// (1 - a) x + a y for frames of identical shape; throws Status::bad_input otherwise.
Frame blend_frames(const Frame& x, const Frame& y, double a);

}  // namespace fest::fluidsim
