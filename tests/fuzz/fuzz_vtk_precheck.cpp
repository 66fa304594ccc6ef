// libFuzzer target: the checks fest makes on a VTK file before VTK parses it
// (formats/dataset/xml_scan.hpp, xml_blocks.hpp, legacy_scan.hpp). They must refuse
// with fest::Error and nothing else: no crash, no read outside the input, no
// allocation the input cannot back.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/dataset/legacy_scan.hpp"
#include "formats/dataset/xml_scan.hpp"
#include "lib/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    if (bytes.substr(0, 5) == "# vtk") {
      fest::formats::detail::scan_legacy_vtk(bytes);
    } else {
      // The type the file names, so that every kind of seed is checked as itself.
      std::string_view expected = "UnstructuredGrid";
      for (std::string_view type : {"ImageData", "PolyData", "StructuredGrid"}) {
        size_t at = bytes.find(type);
        if (at != std::string_view::npos && at < 200) expected = type;
      }
      fest::formats::detail::scan_vtk_xml(bytes, expected, "vtu");
    }
  } catch (const fest::Error&) {
  }
  return 0;
}
