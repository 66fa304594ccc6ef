// Malformed input must give fest::Error(bad_input) with a useful message, never a
// crash, and VTK must not print anything while it happens.

#include <cstdint>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "test_dataset_vtk_adapter.hpp"
#include "lib/core/error.hpp"
#include "test_dataset_samples.hpp"
#include "testdata.hpp"

// VTK 9.1 leaks on some of its own error paths (vtkUnstructuredGridReader::
// ReadMeshSimple, vtkXMLUnstructuredGridReader::ReadPieceData, vtkXMLReader::
// ReadArrayValues), which would fail this executable under FEST_SANITIZE. Leaks of
// memory allocated inside VTK's libraries are therefore not reported here; valid
// reads and writes were checked leak-free without this suppression.
extern "C" const char* __lsan_default_suppressions() { return "leak:libvtk\n"; }

namespace fest::formats {
namespace {

// Reads `bytes`, expecting bad_input whose message contains `needle`, and silence.
void expect_rejected(const std::string& bytes, Format format, const std::string& needle = "") {
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  std::string message;
  bool threw = false;
  try {
    read_vtk(bytes, format);
  } catch (const Error& e) {
    threw = true;
    message = e.what();
    EXPECT_EQ(e.status(), Status::bad_input) << message;
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  ASSERT_TRUE(threw) << "accepted " << format_name(format) << " input of " << bytes.size() << " bytes";
  EXPECT_NE(message.find(needle), std::string::npos) << "message: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "message: " << message;
}

const std::string kLegacyUgHead = "# vtk DataFile Version 4.2\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\n";

std::string garbage(size_t n, uint32_t seed) {
  std::string s(n, '\0');
  for (char& c : s) {
    seed = seed * 1664525u + 1013904223u;
    c = static_cast<char>(seed >> 24);
  }
  return s;
}

TEST(DatasetMalformed, EmptyInput) {
  for (Format f : {Format::vtu, Format::vti, Format::vtp, Format::vtk}) expect_rejected("", f, "empty");
}

TEST(DatasetMalformed, Garbage) {
  for (Format f : {Format::vtu, Format::vti, Format::vtp, Format::vtk})
    for (uint32_t seed = 1; seed <= 8; ++seed) expect_rejected(garbage(100 * seed, seed), f);
  expect_rejected("hello world\n", Format::vtu, "not a VTK XML file");
  expect_rejected("<html><body>hi</body></html>", Format::vtp, "not a VTK XML file");
}

TEST(DatasetMalformed, TruncatedXml) {
  for (bool ascii : {true, false}) {
    DatasetWriteOptions options;
    options.ascii = ascii;
    std::string full = write_dataset(test::make_tets(), Format::vtu, options);
    for (size_t cut : {size_t{1}, size_t{10}, size_t{60}, full.size() / 4, full.size() / 2, full.size() - 40})
      expect_rejected(full.substr(0, cut), Format::vtu);
  }
}

TEST(DatasetMalformed, EveryPrefixOfAFileIsHandled) {
  // A small exhaustive sweep: no prefix may crash or print. An XML prefix fails
  // cleanly unless only trailing whitespace is cut; legacy files have no end
  // marker, so a prefix that ends between sections is a valid smaller dataset.
  for (Format f : {Format::vtu, Format::vtk}) {
    for (bool ascii : {true, false}) {
      DatasetWriteOptions options;
      options.ascii = ascii;
      std::string full = write_dataset(test::make_tets(), f, options);
      testing::internal::CaptureStderr();
      for (size_t cut = 0; cut < full.size(); ++cut) {
        try {
          vtkSmartPointer<vtkDataSet> d = read_vtk(full.substr(0, cut), f);
          if (f == Format::vtu) {
            EXPECT_EQ(d->GetNumberOfCells(), 6) << "prefix " << cut;
          } else {
            EXPECT_TRUE(d->GetNumberOfPoints() == 0 || d->GetNumberOfPoints() == 8) << "prefix " << cut;
            EXPECT_TRUE(d->GetNumberOfCells() == 0 || d->GetNumberOfCells() == 6) << "prefix " << cut;
          }
        } catch (const Error& e) {
          EXPECT_EQ(e.status(), Status::bad_input);
        }
      }
      EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    }
  }
}

TEST(DatasetMalformed, XmlOfAnotherTypePassedAsVtu) {
  std::string vti = write_dataset(test::make_image(), Format::vti);
  expect_rejected(vti, Format::vtu, "ImageData");
  std::string vtu = write_dataset(test::make_tets(), Format::vtu);
  expect_rejected(vtu, Format::vtp, "UnstructuredGrid");
  expect_rejected(vtu, Format::vti, "UnstructuredGrid");
  expect_rejected(vtu, Format::vtk, "first line");
}

TEST(DatasetMalformed, XmlWithAbsurdSizes) {
  std::string huge =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"><UnstructuredGrid>"
      "<Piece NumberOfPoints=\"1000000000000\" NumberOfCells=\"0\"><Points>"
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray>"
      "</Points></Piece></UnstructuredGrid></VTKFile>";
  expect_rejected(huge, Format::vtu, "bytes");
  std::string negative = huge;
  negative.replace(negative.find("1000000000000"), 13, "-5");
  expect_rejected(negative, Format::vtu, "not a count");
  std::string image =
      "<VTKFile type=\"ImageData\" version=\"1.0\"><ImageData WholeExtent=\"0 999 0 999 0 999\" "
      "Origin=\"0 0 0\" Spacing=\"1 1 1\"><Piece Extent=\"0 999 0 999 0 999\"><PointData>"
      "<DataArray type=\"Float64\" Name=\"f\" format=\"ascii\">1</DataArray></PointData>"
      "</Piece></ImageData></VTKFile>";
  expect_rejected(image, Format::vti, "bytes");
  std::string endless = image;
  for (size_t at = endless.find("999"); at != std::string::npos; at = endless.find("999", at + 9))
    endless.replace(at, 3, "999999999");
  expect_rejected(endless, Format::vti, "2^40");
}

TEST(DatasetMalformed, XmlWithShortArray) {
  // Declares three points but gives two.
  std::string s =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"><UnstructuredGrid>"
      "<Piece NumberOfPoints=\"3\" NumberOfCells=\"0\"><Points>"
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 1 1</DataArray>"
      "</Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\"></DataArray>"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"></DataArray>"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray></Cells>"
      "</Piece></UnstructuredGrid></VTKFile>";
  expect_rejected(s, Format::vtu);
}

std::string one_tet_vtu(const std::string& connectivity, const std::string& offsets, const std::string& types) {
  return "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"><UnstructuredGrid>"
         "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>"
         "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1</DataArray>"
         "</Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         connectivity + "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
         "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + types +
         "</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>";
}

TEST(DatasetMalformed, XmlCellsThatDoNotAddUp) {
  EXPECT_NO_THROW(read_vtk(one_tet_vtu("0 1 2 3", "4", "10"), Format::vtu));
  expect_rejected(one_tet_vtu("0 1 2 9", "4", "10"), Format::vtu, "point 9");
  expect_rejected(one_tet_vtu("0 1 2 -1", "4", "10"), Format::vtu);
  expect_rejected(one_tet_vtu("0 1 2", "3", "10"), Format::vtu, "points instead of 4");
  expect_rejected(one_tet_vtu("0 1 2 3", "4", "200"), Format::vtu, "type 200");
  // The reader sizes the connectivity by the last offset before reading any id.
  expect_rejected(one_tet_vtu("0 1 2 3", "4000000000000", "10"), Format::vtu, "offsets end at");
}

TEST(DatasetMalformed, LegacyHeaderOnly) {
  expect_rejected("# vtk DataFile Version 4.2\n", Format::vtk);
  expect_rejected("# vtk DataFile Version 4.2\ntitle\n", Format::vtk);
  expect_rejected("# vtk DataFile Version 4.2\ntitle\nASCII\n", Format::vtk, "DATASET");
  expect_rejected(kLegacyUgHead, Format::vtk);
  expect_rejected("# vtk DataFile Version 4.2\ntitle\nTEXT\nDATASET POLYDATA\n", Format::vtk, "ASCII or BINARY");
  expect_rejected("# vtk DataFile Version 4.2\ntitle\nASCII\nDATASET GRAPH\n", Format::vtk, "dataset type");
  expect_rejected("# not vtk\n", Format::vtk, "first line");
}

TEST(DatasetMalformed, LegacyPointCountBeyondTheData) {
  expect_rejected(kLegacyUgHead + "POINTS 100 float\n0 0 0 1 1 1\n", Format::vtk, "POINTS");
  expect_rejected(kLegacyUgHead + "POINTS 999999999999 float\n0 0 0\n", Format::vtk, "remaining bytes");
  expect_rejected(kLegacyUgHead + "POINTS -3 float\n0 0 0\n", Format::vtk, "not a count");
  std::string binary = "# vtk DataFile Version 4.2\ntest\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n";
  binary += std::string(12, '\0');  // one point of four
  expect_rejected(binary, Format::vtk, "bytes");
}

TEST(DatasetMalformed, LegacyCellListsThatDoNotAddUp) {
  const std::string points = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n";
  // A valid file first, so the rejections below are about the one thing changed.
  EXPECT_NO_THROW(read_vtk(kLegacyUgHead + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n", Format::vtk));
  // A cell claims 100 points in a list of 5 values: VTK would write past its buffer.
  expect_rejected(kLegacyUgHead + points + "CELLS 1 5\n100 0 1 2 3\nCELL_TYPES 1\n10\n", Format::vtk, "overruns");
  expect_rejected(kLegacyUgHead + points + "CELLS 1 6\n4 0 1 2 3 3\nCELL_TYPES 1\n10\n", Format::vtk, "values of");
  expect_rejected(kLegacyUgHead + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 2\n10 10\n", Format::vtk,
                  "CELL_TYPES");
  expect_rejected(kLegacyUgHead + points + "CELLS 1 5\n4 0 1 2 7\nCELL_TYPES 1\n10\n", Format::vtk, "point 7");
  expect_rejected(kLegacyUgHead + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n42\n", Format::vtk, "polyhedron");
  expect_rejected(kLegacyUgHead + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n5\n", Format::vtk, "instead of 3");
}

TEST(DatasetMalformed, LegacyAttributesThatDoNotFit) {
  const std::string body = "POINTS 2 float\n0 0 0 1 1 1\n";
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 2\nSCALARS s float 99999999\nLOOKUP_TABLE default\n1 2\n",
                  Format::vtk);
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 2\nSCALARS % float\nLOOKUP_TABLE default\n1 2\n", Format::vtk,
                  "hex");
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 2\nFIELD f 99999999\n", Format::vtk, "FIELD");
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 2\nSCALARS s float\nLOOKUP_TABLE default\n1\n", Format::vtk);
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 3\nSCALARS s float\nLOOKUP_TABLE default\n1 2 3\n",
                  Format::vtk);
  expect_rejected(kLegacyUgHead + body + "POINT_DATA 2\nSCALARS s complex\nLOOKUP_TABLE default\n1 2\n",
                  Format::vtk, "data type");
}

TEST(DatasetMalformed, LegacyAsciiValueThatIsNotANumber) {
  // VTK stops at "POINT_DATA" inside the short array and reads on from there, taking
  // the huge count that follows for the point count.
  const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET STRUCTURED_POINTS\n"
                           "DIMENSIONS 2 1 1\nSPACING 1 1 1\nORIGIN 0 0 0\n";
  expect_rejected(head + "POINT_DATA 2\nSCALARS a int\nLOOKUP_TABLE default\n1\nPOINT_DATA 99999999999\n",
                  Format::vtk, "not a number");
  expect_rejected(head + "POINT_DATA 2\nSCALARS a int\nLOOKUP_TABLE default\n1 2.5\n", Format::vtk, "not a number");
  expect_rejected(head + "POINT_DATA 2\nSCALARS a float\nLOOKUP_TABLE default\n1 2x\n", Format::vtk, "not a number");
  EXPECT_NO_THROW(read_vtk(head + "POINT_DATA 2\nSCALARS a float\nLOOKUP_TABLE default\n-1.5e+3 .25\n", Format::vtk));
}

TEST(DatasetMalformed, LegacyGridWithoutDimensionsFirst) {
  const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET STRUCTURED_GRID\n";
  expect_rejected(head, Format::vtk, "DIMENSIONS");
  expect_rejected(head + "POINTS 1 float\n0 0 0\nDIMENSIONS 1 1 1\n", Format::vtk, "DIMENSIONS must come before");
}

TEST(DatasetMalformed, LegacyBinaryStringLengthsBeyondTheData) {
  std::string s = "# vtk DataFile Version 4.2\ntest\nBINARY\nDATASET POLYDATA\nFIELD fd 1\nnames 1 1 string\n";
  s += std::string("\x00\x00\x00\x10\x00\x00\x00\x00", 8);  // 64-bit length prefix: 2^60 bytes
  s += "abc\n";
  expect_rejected(s, Format::vtk, "bytes");
}

}  // namespace
}  // namespace fest::formats

namespace fest::formats {
namespace {

// A deterministic mutation sweep (this area has no libFuzzer target): flip, insert
// and delete bytes of valid files in every format; only fest::Error may come out.
// FEST_DATASET_MUTATIONS=N runs N rounds per seed file instead of 150;
// FEST_DATASET_MUTATION_DUMP=path writes each input there before reading it.
TEST(DatasetMalformed, MutatedFilesFailCleanly) {
  const char* rounds_env = std::getenv("FEST_DATASET_MUTATIONS");
  const int rounds = rounds_env ? std::atoi(rounds_env) : 150;
  const char* dump = std::getenv("FEST_DATASET_MUTATION_DUMP");
  struct Seed {
    vtkSmartPointer<vtkDataSet> dataset;
    Format format;
  };
  std::vector<Seed> seeds = {{test::make_tets(), Format::vtu}, {test::make_image(), Format::vti},
                             {test::make_poly(), Format::vtp}, {test::make_tets(), Format::vtk},
                             {test::make_poly(), Format::vtk}, {test::make_image(), Format::vtk},
                             {test::make_structured_grid(), Format::vtk},
                             {test::make_rectilinear_grid(), Format::vtk}};
  uint32_t state = 12345;
  auto next = [&state](uint32_t bound) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % bound;
  };
  const char* interesting[] = {"0", "-1", "9", "99999999", "1e9", "%", " ", "\n", "<", ">", "\"", "42", "2147483648"};
  testing::internal::CaptureStderr();
  for (const Seed& seed : seeds) {
    for (bool ascii : {true, false}) {
      DatasetWriteOptions options;
      options.ascii = ascii;
      const std::string original = write_dataset(seed.dataset, seed.format, options);
      for (int round = 0; round < rounds; ++round) {
        std::string bytes = original;
        for (uint32_t edits = 1 + next(3); edits > 0; --edits) {
          size_t at = next(static_cast<uint32_t>(bytes.size()));
          switch (next(4)) {
            case 0: bytes[at] = static_cast<char>(next(256)); break;
            case 1: bytes.insert(at, interesting[next(sizeof interesting / sizeof *interesting)]); break;
            case 2: bytes.erase(at, 1 + next(8)); break;
            default: bytes.replace(at, 1, interesting[next(sizeof interesting / sizeof *interesting)]); break;
          }
          if (bytes.empty()) bytes = "x";
        }
        if (dump != nullptr) {  // the input about to be read, for a crash to leave behind
          std::ofstream(dump, std::ios::binary | std::ios::trunc) << bytes;
        }
        try {
          read_vtk(bytes, seed.format);
        } catch (const Error& e) {
          EXPECT_EQ(e.status(), Status::bad_input) << e.what();
        }
      }
    }
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace fest::formats

namespace fest::formats {
namespace {

// Inputs that once crashed or exhausted memory (tests/data/regress/dataset/, named
// for what they exercise). Each must now fail cleanly and quietly.
TEST(DatasetMalformed, RegressionInputs) {
  const std::string dir = test::fixture("regress/dataset");
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    Format format = ext == ".vtu" ? Format::vtu : ext == ".vti" ? Format::vti : ext == ".vtp" ? Format::vtp : Format::vtk;
    if (ext != ".vtu" && ext != ".vti" && ext != ".vtp" && ext != ".vtk") continue;
    SCOPED_TRACE(entry.path().filename().string());
    expect_rejected(test::slurp(entry.path().string()), format);
    ++replayed;
  }
  EXPECT_GE(replayed, 3);
}

}  // namespace
}  // namespace fest::formats
