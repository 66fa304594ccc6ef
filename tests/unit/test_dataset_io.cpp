// Round trips through every format each sample fits, in ASCII and binary: the data
// read back must equal the data written, value for value; writing is deterministic.

#include <string>

#include <gtest/gtest.h>
#include <vtkDataWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkStructuredGridWriter.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkPolyData.h>

#include "test_dataset_vtk_adapter.hpp"
#include "lib/core/error.hpp"
#include "test_dataset_samples.hpp"

namespace fest::formats {
namespace {

using test::expect_same_dataset;

struct Case {
  const char* name;
  vtkSmartPointer<vtkDataSet> (*make)();
  Format format;
  bool ascii;
};

vtkSmartPointer<vtkDataSet> image() { return test::make_image(); }
vtkSmartPointer<vtkDataSet> tets() { return test::make_tets(); }
vtkSmartPointer<vtkDataSet> poly() { return test::make_poly(); }
vtkSmartPointer<vtkDataSet> structured() { return test::make_structured_grid(); }
vtkSmartPointer<vtkDataSet> rectilinear() { return test::make_rectilinear_grid(); }

class DatasetRoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(DatasetRoundTrip, ReadsBackWhatItWrote) {
  const Case& c = GetParam();
  vtkSmartPointer<vtkDataSet> original = c.make();
  DatasetWriteOptions options;
  options.ascii = c.ascii;
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  std::string bytes = write_dataset(original, c.format, options);
  vtkSmartPointer<vtkDataSet> back = read_vtk(bytes, c.format);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  ASSERT_FALSE(bytes.empty());
  expect_same_dataset(original, back);
}

TEST_P(DatasetRoundTrip, WritingIsDeterministic) {
  const Case& c = GetParam();
  DatasetWriteOptions options;
  options.ascii = c.ascii;
  std::string first = write_dataset(c.make(), c.format, options);
  std::string second = write_dataset(c.make(), c.format, options);
  EXPECT_EQ(first, second);
  // And what was read back writes the same bytes again.
  std::string again = write_dataset(read_vtk(first, c.format), c.format, options);
  EXPECT_EQ(first, again);
}

TEST_P(DatasetRoundTrip, AsciiAndBinaryAreWhatWasAskedFor) {
  const Case& c = GetParam();
  DatasetWriteOptions options;
  options.ascii = c.ascii;
  std::string bytes = write_dataset(c.make(), c.format, options);
  if (c.format == Format::vtk) {
    EXPECT_NE(bytes.find(c.ascii ? "\nASCII\n" : "\nBINARY\n"), std::string::npos);
  } else {
    EXPECT_EQ(bytes.find("compressor="), std::string::npos);  // uncompressed
    if (c.ascii) {
      EXPECT_EQ(bytes.find("<AppendedData"), std::string::npos);
      EXPECT_NE(bytes.find("format=\"ascii\""), std::string::npos);
    } else {
      EXPECT_NE(bytes.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllFormats, DatasetRoundTrip,
    ::testing::Values(Case{"image_vti_binary", image, Format::vti, false}, Case{"image_vti_ascii", image, Format::vti, true},
                      Case{"image_vtk_binary", image, Format::vtk, false}, Case{"image_vtk_ascii", image, Format::vtk, true},
                      Case{"tets_vtu_binary", tets, Format::vtu, false}, Case{"tets_vtu_ascii", tets, Format::vtu, true},
                      Case{"tets_vtk_binary", tets, Format::vtk, false}, Case{"tets_vtk_ascii", tets, Format::vtk, true},
                      Case{"poly_vtp_binary", poly, Format::vtp, false}, Case{"poly_vtp_ascii", poly, Format::vtp, true},
                      Case{"poly_vtk_binary", poly, Format::vtk, false}, Case{"poly_vtk_ascii", poly, Format::vtk, true},
                      Case{"structured_vtk_binary", structured, Format::vtk, false},
                      Case{"structured_vtk_ascii", structured, Format::vtk, true},
                      Case{"rectilinear_vtk_binary", rectilinear, Format::vtk, false},
                      Case{"rectilinear_vtk_ascii", rectilinear, Format::vtk, true},
                      Case{"structured_vts_binary", structured, Format::vts, false},
                      Case{"structured_vts_ascii", structured, Format::vts, true}),
    [](const ::testing::TestParamInfo<Case>& param_info) { return std::string(param_info.param.name); });

// Files from older VTK (version 4.2: cells as "n id id ..." lists, not offsets).
// vtkDataSetWriter does not pass the version on, so the specific writers are used.
std::string write_version_42(vtkDataSet* dataset, bool ascii) {
  vtkSmartPointer<vtkDataWriter> writer;
  if (dataset->IsA("vtkUnstructuredGrid")) writer = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
  if (dataset->IsA("vtkPolyData")) writer = vtkSmartPointer<vtkPolyDataWriter>::New();
  if (dataset->IsA("vtkImageData")) writer = vtkSmartPointer<vtkStructuredPointsWriter>::New();
  if (dataset->IsA("vtkStructuredGrid")) writer = vtkSmartPointer<vtkStructuredGridWriter>::New();
  if (dataset->IsA("vtkRectilinearGrid")) writer = vtkSmartPointer<vtkRectilinearGridWriter>::New();
  writer->SetInputData(dataset);
  writer->SetFileVersion(42);
  writer->WriteToOutputStringOn();
  if (ascii) {
    writer->SetFileTypeToASCII();
  } else {
    writer->SetFileTypeToBinary();
  }
  EXPECT_TRUE(writer->Write());
  return writer->GetOutputStdString();
}

TEST(DatasetRoundTrip, ReadsLegacyVersion42Files) {
  for (auto make : {image, tets, poly, structured, rectilinear}) {
    for (bool ascii : {true, false}) {
      vtkSmartPointer<vtkDataSet> original = make();
      std::string bytes = write_version_42(original, ascii);
      ASSERT_EQ(bytes.rfind("# vtk DataFile Version 4.2", 0), 0u);
      test::expect_same_dataset(original, read_vtk(bytes, Format::vtk));
    }
  }
}

// VTK 9.1's structured grid reader crashed on any array whose name starts with
// "field" (its metadata pass took the name for a FIELD block).
TEST(DatasetRoundTrip, ArraysNamedLikeKeywords) {
  for (auto make : {image, tets, poly, structured, rectilinear}) {
    vtkSmartPointer<vtkDataSet> original = make();
    for (const char* name : {"field_x", "POINTS", "cells", "dimensions", "scalars", "lookup_table"}) {
      auto values = vtkSmartPointer<vtkDoubleArray>::New();
      values->SetName(name);
      for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i) values->InsertNextValue(0.5 * i);
      original->GetPointData()->AddArray(values);
    }
    for (bool ascii : {true, false}) {
      DatasetWriteOptions options;
      options.ascii = ascii;
      test::expect_same_dataset(original, read_vtk(write_dataset(original, Format::vtk, options), Format::vtk));
      test::expect_same_dataset(original, read_vtk(write_version_42(original, ascii), Format::vtk));
    }
  }
}

TEST(DatasetRoundTrip, ReadsTheRightTypeBack) {
  EXPECT_TRUE(read_vtk(write_dataset(test::make_tets(), Format::vtk), Format::vtk)->IsA("vtkUnstructuredGrid"));
  EXPECT_TRUE(read_vtk(write_dataset(test::make_poly(), Format::vtk), Format::vtk)->IsA("vtkPolyData"));
  EXPECT_TRUE(read_vtk(write_dataset(test::make_image(), Format::vtk), Format::vtk)->IsA("vtkImageData"));
  EXPECT_TRUE(read_vtk(write_dataset(structured(), Format::vtk), Format::vtk)->IsA("vtkStructuredGrid"));
  EXPECT_TRUE(read_vtk(write_dataset(rectilinear(), Format::vtk), Format::vtk)->IsA("vtkRectilinearGrid"));
  EXPECT_STREQ(read_vtk(write_dataset(test::make_image(), Format::vti), Format::vti)->GetClassName(), "vtkImageData");
}

TEST(DatasetRoundTrip, EmptyDatasetsSurvive) {
  auto empty_grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  for (Format f : {Format::vtu, Format::vtk}) {
    vtkSmartPointer<vtkDataSet> back = read_vtk(write_dataset(empty_grid, f), f);
    EXPECT_EQ(back->GetNumberOfPoints(), 0);
    EXPECT_EQ(back->GetNumberOfCells(), 0);
  }
  auto empty_poly = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkDataSet> back = read_vtk(write_dataset(empty_poly, Format::vtp), Format::vtp);
  EXPECT_EQ(back->GetNumberOfPoints(), 0);
}

void expect_bad_input(vtkDataSet* dataset, Format format) {
  try {
    write_dataset(dataset, format);
    ADD_FAILURE() << (dataset ? dataset->GetClassName() : "null") << " was written as " << format_name(format);
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input) << e.what();
  }
}

TEST(DatasetWrite, RefusesTypesTheFormatCannotHold) {
  expect_bad_input(test::make_poly(), Format::vti);
  expect_bad_input(test::make_poly(), Format::vtu);
  expect_bad_input(test::make_image(), Format::vtu);
  expect_bad_input(test::make_image(), Format::vtp);
  expect_bad_input(test::make_tets(), Format::vtp);
  expect_bad_input(test::make_tets(), Format::vti);
  expect_bad_input(structured(), Format::vtu);
  expect_bad_input(rectilinear(), Format::vti);
  expect_bad_input(nullptr, Format::vtk);
}

TEST(DatasetWrite, RefusesFormatsThatAreNotDatasets) {
  EXPECT_THROW(write_dataset(test::make_tets(), Format::ply), Error);
  EXPECT_THROW(read_vtk("x", Format::png), Error);
}

}  // namespace
}  // namespace fest::formats
