#pragma once
// VTK image data (.vti, as fluidsim writes it) read into a Frame: shared by `render`
// (fields to draw) and `run --init` (starting state), so both read the same layout.

#include "core/dataset.hpp"
#include "fluidsim/frame.hpp"

namespace fest::fluidsim_tool {

// What to do with a point array that has no name.
enum class UnnamedArrays { name_by_index, skip };

// Sets dim, size and spacing from the image and appends every numeric point array as a
// field, channels interleaved in array order (channel fastest, then x, y, z). Unnamed
// arrays are called "array<i>" (i: the array's index) or left out.
void read_image_data_frame(const Dataset& image, fluidsim::Frame& frame, UnnamedArrays unnamed);

}  // namespace fest::fluidsim_tool
