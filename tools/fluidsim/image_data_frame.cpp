#include "image_data_frame.hpp"

#include <vector>

#include <fmt/format.h>

namespace fest::fluidsim_tool {

void read_image_data_frame(const Dataset& image, fluidsim::Frame& f, UnnamedArrays unnamed) {
  const auto dims = image.dimensions();
  f.dim = dims[2] == 1 ? 2 : 3;
  f.size = {dims[0], dims[1], dims[2]};
  f.spacing = image.spacing[0];
  std::vector<const DataArray*> arrays;
  for (std::size_t a = 0; a < image.point_data.size(); ++a) {
    const DataArray& arr = image.point_data[a];
    // String arrays are not fields (VTK's GetArray does not return them either).
    if (!arr.numeric() || (arr.name.empty() && unnamed == UnnamedArrays::skip)) continue;
    f.fields.push_back({arr.name.empty() ? fmt::format("array{}", a) : arr.name, arr.components});
    arrays.push_back(&arr);
  }
  const int C = f.channels();
  f.data.resize(f.nodes() * C);
  int c0 = 0;
  for (const DataArray* arr : arrays) {
    for (std::size_t n = 0; n < f.nodes(); ++n)
      for (int k = 0; k < arr->components; ++k) f.data[n * C + c0 + k] = arr->component(n, k);
    c0 += arr->components;
  }
}

}  // namespace fest::fluidsim_tool
