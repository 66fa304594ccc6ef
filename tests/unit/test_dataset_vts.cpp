// VTK XML structured grids (.vts): recognised by content, and refused cleanly when the
// file is cut short or holds another dataset type.

#include <string>

#include <gtest/gtest.h>

#include "test_dataset_vtk_adapter.hpp"
#include "formats/detect.hpp"
#include "lib/core/error.hpp"
#include "test_dataset_samples.hpp"

namespace fest::formats {
namespace {

TEST(DatasetVts, RecognisedByContentAndNamed) {
  const std::string bytes = write_dataset(test::make_structured_grid(), Format::vts);
  EXPECT_EQ(detect_format(bytes), Format::vts);
  EXPECT_STREQ(format_name(Format::vts), "vts");
  EXPECT_EQ(output_format_from_path("grid.vts").format, Format::vts);
}

TEST(DatasetVts, TruncatedFileIsBadInput) {
  const std::string bytes = write_dataset(test::make_structured_grid(), Format::vts);
  // Cuts inside the markup and at the start of the raw appended data. (A cut inside the
  // last appended array is not caught: vtkXMLStructuredGridReader reports nothing.)
  for (std::size_t keep : {std::size_t{200}, bytes.size() / 2, bytes.find("<AppendedData") + 40}) {
    try {
      read_vtk(bytes.substr(0, keep), Format::vts);
      ADD_FAILURE() << "a .vts cut at " << keep << " bytes was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input);
    }
  }
}

TEST(DatasetVts, OtherDatasetTypesAreNotWrittenAsVts) {
  try {
    write_dataset(test::make_tets(), Format::vts);
    ADD_FAILURE() << "an unstructured grid was written as .vts";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
  }
}

}  // namespace
}  // namespace fest::formats
