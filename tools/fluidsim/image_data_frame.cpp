#include "image_data_frame.hpp"

#include <vector>

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

namespace fest::fluidsim_tool {

void read_image_data_frame(vtkImageData* image, fluidsim::Frame& f, UnnamedArrays unnamed) {
  int dims[3];
  image->GetDimensions(dims);
  f.dim = dims[2] == 1 ? 2 : 3;
  f.size = {dims[0], dims[1], dims[2]};
  f.spacing = image->GetSpacing()[0];
  vtkPointData* pd = image->GetPointData();
  std::vector<vtkDataArray*> arrays;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
    vtkDataArray* arr = pd->GetArray(a);
    if (!arr || (!arr->GetName() && unnamed == UnnamedArrays::skip)) continue;
    f.fields.push_back({arr->GetName() ? arr->GetName() : fmt::format("array{}", a), arr->GetNumberOfComponents()});
    arrays.push_back(arr);
  }
  const int C = f.channels();
  f.data.resize(f.nodes() * C);
  int c0 = 0;
  for (vtkDataArray* arr : arrays) {
    for (std::size_t n = 0; n < f.nodes(); ++n)
      for (int k = 0; k < arr->GetNumberOfComponents(); ++k)
        f.data[n * C + c0 + k] = arr->GetComponent(static_cast<vtkIdType>(n), k);
    c0 += arr->GetNumberOfComponents();
  }
}

}  // namespace fest::fluidsim_tool
