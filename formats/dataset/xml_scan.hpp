#pragma once
// A look at the XML markup of a .vtu/.vti/.vtp file before VTK reads it.
//
// vtkXMLReader allocates every array for the sizes the markup declares
// (NumberOfPoints, Extent, NumberOfComponents) before it reads the data, so a
// 200-byte file can ask for terabytes. This scan adds up what the declared arrays
// need and refuses what the input cannot hold (allowing for compression), checks
// that the file is of the expected type, for a clear message, and then checks every
// DataArray's data against its markup (xml_blocks.hpp).

#include <cstdint>
#include <string_view>

namespace fest::formats::detail {

struct XmlLimits {
  // The most values an array whose length comes from the data itself (cell
  // connectivity, sized by the last cell offset) can plausibly have in this input.
  uint64_t max_data_driven_values = 0;
};

// `expected_type` is the VTKFile type attribute ("UnstructuredGrid", "ImageData",
// "PolyData"); `format` names the format in messages ("vtu"). Throws bad_input.
XmlLimits scan_vtk_xml(std::string_view bytes, std::string_view expected_type, const char* format);

}  // namespace fest::formats::detail
