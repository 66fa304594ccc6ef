#pragma once
// fest::Dataset <-> VTK data objects. Used inside the VTK plugin (vtk_plugin.cpp) and by
// tests and benchmarks that hand fest's datasets to VTK directly; tools never include it.

#include <vtkSmartPointer.h>

#include "core/dataset.hpp"

class vtkDataSet;

namespace fest::formats {

// Throws bad_input("<format>: ...") for content a Dataset cannot carry (arrays of
// variant or unicode type, colour maps other than a lookup table, polyhedron face
// lists), naming what and how many.
Dataset from_vtk(vtkDataSet* dataset, const char* format = "vtk");
vtkSmartPointer<vtkDataSet> to_vtk(const Dataset& dataset);

}  // namespace fest::formats
