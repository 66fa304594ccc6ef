// The check fest makes on VTK XML files before VTK reads them (formats/dataset/
// xml_scan.hpp, xml_blocks.hpp): every encoding VTK's own writers produce is accepted
// and read back unchanged; the same bytes under attributes that no longer match them
// are refused with one line naming the array; the files in tests/data/vtk_bad/
// (fuzzer findings and hand-made cases) are refused, quietly, except the ok_* ones.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "lib/core/error.hpp"
#include "test_dataset_samples.hpp"
#include "test_dataset_vtk_adapter.hpp"
#include "testdata.hpp"

namespace fest::formats {
namespace {

struct Encoding {
  bool header64, big_endian, zlib;
  int mode;  // vtkXMLWriter::Ascii, Binary, Appended
  bool base64_appended;
  std::string name() const {
    static const char* modes[] = {"ascii", "binary", "appended"};
    return std::string(header64 ? "UInt64" : "UInt32") + (big_endian ? "_BE" : "_LE") + (zlib ? "_zlib_" : "_") +
           modes[mode] + (mode == 2 ? (base64_appended ? "_base64" : "_raw") : "");
  }
};

std::vector<Encoding> every_encoding() {
  std::vector<Encoding> all;
  for (bool h : {false, true})
    for (bool be : {false, true})
      for (bool z : {false, true})
        for (int mode : {0, 1, 2})
          for (bool b64 : {false, true})
            if (mode == 2 || !b64) all.push_back({h, be, z, mode, b64});
  return all;
}

template <typename Writer>
std::string write_with_vtk(vtkDataSet* dataset, const Encoding& e) {
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(dataset);
  writer->WriteToOutputStringOn();
  if (e.header64) {
    writer->SetHeaderTypeToUInt64();
  } else {
    writer->SetHeaderTypeToUInt32();
  }
  if (e.big_endian) {
    writer->SetByteOrderToBigEndian();
  } else {
    writer->SetByteOrderToLittleEndian();
  }
  if (e.zlib) {
    writer->SetCompressorTypeToZLib();
    writer->SetBlockSize(64);  // several compressed blocks per array
  } else {
    writer->SetCompressorTypeToNone();
  }
  writer->SetDataMode(e.mode);
  writer->SetEncodeAppendedData(e.base64_appended);
  EXPECT_EQ(writer->Write(), 1);
  return writer->GetOutputString();
}

vtkSmartPointer<vtkUnstructuredGrid> tets_with_strings() {
  vtkSmartPointer<vtkUnstructuredGrid> grid = test::make_tets();
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("kind");
  names->InsertNextValue("rotation");
  names->InsertNextValue("");
  names->InsertNextValue("x y");
  grid->GetFieldData()->AddArray(names);
  return grid;
}

std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// Reads `bytes`, expecting bad_input with one line containing `needle`, and silence.
void expect_refused(const std::string& bytes, Format format, const std::string& needle) {
  testing::internal::CaptureStderr();
  std::string message;
  try {
    read_vtk(bytes, format);
  } catch (const Error& e) {
    message = e.what();
    EXPECT_EQ(e.status(), Status::bad_input) << message;
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_NE(message.find(needle), std::string::npos) << "message: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(DatasetPrecheck, EveryEncodingVtkWritesReadsBackUnchanged) {
  vtkSmartPointer<vtkUnstructuredGrid> tets = tets_with_strings();
  vtkSmartPointer<vtkPolyData> poly = test::make_poly();
  vtkSmartPointer<vtkImageData> image = test::make_image();
  vtkSmartPointer<vtkStructuredGrid> grid = test::make_structured_grid();
  for (const Encoding& e : every_encoding()) {
    SCOPED_TRACE(e.name());
    test::expect_same_dataset(tets, read_vtk(write_with_vtk<vtkXMLUnstructuredGridWriter>(tets, e), Format::vtu));
    test::expect_same_dataset(poly, read_vtk(write_with_vtk<vtkXMLPolyDataWriter>(poly, e), Format::vtp));
    test::expect_same_dataset(image, read_vtk(write_with_vtk<vtkXMLImageDataWriter>(image, e), Format::vti));
    test::expect_same_dataset(grid, read_vtk(write_with_vtk<vtkXMLStructuredGridWriter>(grid, e), Format::vts));
  }
}

// The attributes changed, the bytes not: every binary encoding is refused by name.
TEST(DatasetPrecheck, AttributesThatNoLongerMatchTheBytesAreRefused) {
  vtkSmartPointer<vtkUnstructuredGrid> tets = tets_with_strings();
  for (const Encoding& e : every_encoding()) {
    if (e.mode == 0) continue;  // ASCII has no block headers
    SCOPED_TRACE(e.name());
    const std::string good = write_with_vtk<vtkXMLUnstructuredGridWriter>(tets, e);
    const std::string header = e.header64 ? "header_type=\"UInt64\"" : "header_type=\"UInt32\"";
    const std::string order = e.big_endian ? "byte_order=\"BigEndian\"" : "byte_order=\"LittleEndian\"";
    expect_refused(replace_once(good, header, e.header64 ? "header_type=\"UInt32\"" : "header_type=\"UInt64\""),
                   Format::vtu, "DataArray \"");
    expect_refused(replace_once(good, order, e.big_endian ? "byte_order=\"LittleEndian\"" : "byte_order=\"BigEndian\""),
                   Format::vtu, "DataArray \"");
    expect_refused(replace_once(good, "type=\"Float64\"", "type=\"Flaot64\""), Format::vtu,
                   "type \"Flaot64\" is not a VTK type");
  }
}

TEST(DatasetPrecheck, BadAttributesAreNamed) {
  Encoding raw{true, false, false, 2, false};
  const std::string good = write_with_vtk<vtkXMLUnstructuredGridWriter>(tets_with_strings(), raw);
  expect_refused(replace_once(good, "header_type=\"UInt64\"", "header_type=\"UInt16\""), Format::vtu,
                 "neither UInt32 nor UInt64");
  expect_refused(replace_once(good, "byte_order=\"LittleEndian\"", "byte_order=\"Middle\""), Format::vtu,
                 "neither LittleEndian nor BigEndian");
  expect_refused(replace_once(good, "encoding=\"raw\"", "encoding=\"hex\""), Format::vtu, "neither raw nor base64");
  expect_refused(replace_once(good, "format=\"appended\"", "format=\"text\""), Format::vtu,
                 "is not ascii, binary or appended");
  expect_refused(replace_once(good, "offset=\"0\"", "offset=\"-8\""), Format::vtu, "offset \"-8\" is not a byte offset");
  expect_refused(replace_once(good, "offset=\"0\"", "offset=\"99999999\""), Format::vtu, "past the end");
  expect_refused(replace_once(good, "type=\"Float64\"", "type=\"\\x01\\x02\""), Format::vtu, "is not a VTK type");
}

// Fuzzer findings and hand-made cases; ok_* are legal files that must read.
TEST(DatasetPrecheck, VtkBadFixtures) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::fixture("vtk_bad"))) {
    const std::string name = entry.path().filename().string();
    const std::string ext = entry.path().extension().string();
    const Format format = ext == ".vti" ? Format::vti : ext == ".vtp" ? Format::vtp : ext == ".vts" ? Format::vts
                          : ext == ".vtk" ? Format::vtk : Format::vtu;
    SCOPED_TRACE(name);
    const std::string bytes = test::slurp(entry.path().string());
    if (name.rfind("ok_", 0) == 0) {
      EXPECT_NO_THROW(read_vtk(bytes, format));
    } else {
      expect_refused(bytes, format, "");
    }
    ++replayed;
  }
  EXPECT_GE(replayed, 8);
}

}  // namespace
}  // namespace fest::formats
