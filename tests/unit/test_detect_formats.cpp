#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "formats/detect.hpp"

using fest::formats::Format;
using fest::formats::detect_format;

namespace {

Format detect(const std::string& s) { return detect_format(s, "test"); }

std::string nifti_header(bool big_endian) {
  std::string h(352, '\0');
  std::int32_t n = 348;
  if (big_endian) n = static_cast<std::int32_t>(__builtin_bswap32(348u));
  std::memcpy(h.data(), &n, 4);
  std::memcpy(h.data() + 344, "n+1\0", 4);
  return h;
}

std::string binary_stl(std::uint32_t triangles, const char* header_text) {
  std::string s(80, ' ');
  std::memcpy(s.data(), header_text, std::strlen(header_text));
  s.append(reinterpret_cast<const char*>(&triangles), 4);
  s.append(50 * triangles, '\0');
  return s;
}

}  // namespace

TEST(Detect, BinarySignatures) {
  EXPECT_EQ(detect("\x89PNG\r\n\x1a\n...."), Format::png);
  EXPECT_EQ(detect(std::string("\x76\x2f\x31\x01\x02\0\0\0", 8)), Format::exr);
  EXPECT_EQ(detect(std::string("II*\0\x08\0\0\0", 8)), Format::tiff);
  EXPECT_EQ(detect(std::string("MM\0*\0\0\0\x08", 8)), Format::tiff);
  EXPECT_EQ(detect("DRACO\x02\x02"), Format::drc);
  EXPECT_EQ(detect("NRRD0004\ntype: float\n"), Format::nrrd);
  EXPECT_EQ(detect(nifti_header(false)), Format::nifti);
  EXPECT_EQ(detect(nifti_header(true)), Format::nifti);
}

// Scene formats read through assimp: the signatures each format's specification fixes.
TEST(Detect, SceneFormats) {
  using namespace fest::formats;
  EXPECT_EQ(detect(std::string("glTF\x02\0\0\0\x14\0\0\0", 12)), Format::glb);
  EXPECT_EQ(detect(R"({"asset":{"version":"2.0"},"meshes":[]})"), Format::gltf);
  EXPECT_EQ(detect(R"({"asset":{"version":"2.0"}})"), Format::json);  // no geometry: plain JSON
  EXPECT_EQ(detect("<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"x\" version=\"1.4.1\">"), Format::dae);
  EXPECT_EQ(detect(std::string("Kaydara FBX Binary  \0\x1a\0", 23)), Format::fbx);
  EXPECT_EQ(detect("; FBX 7.4.0 project file\n"), Format::fbx);
  EXPECT_EQ(detect("xof 0303txt 0032\n"), Format::xfile);
  EXPECT_EQ(detect(std::string("FORM\0\0\0\x04LWO2", 12)), Format::lwo);
  // 3DS: main chunk 0x4D4D of the file's length (16), then the version chunk 0x0002.
  EXPECT_EQ(detect(std::string("\x4d\x4d\x10\0\0\0\x02\0\x0a\0\0\0\x03\0\0\0", 16)), Format::threeds);
  // A 3DS file of 10752 = 0x2A00 bytes starts "MM\0*", TIFF's big-endian magic: its
  // chunk length and version chunk decide (found by writing tests/fuzz/fuzz_scene_detect).
  std::string tiff_like(10752, '\0');
  tiff_like.replace(0, 8, std::string("\x4d\x4d\x00\x2a\0\0\x02\0", 8));
  EXPECT_EQ(detect(tiff_like), Format::threeds);
  EXPECT_EQ(detect(std::string("MM\0*\0\0\0\x08", 8)), Format::tiff);  // a TIFF stays a TIFF
  EXPECT_EQ(kind_of(Format::glb), Kind::mesh);
  EXPECT_TRUE(read_only_scene_format(Format::fbx));
  EXPECT_FALSE(read_only_scene_format(Format::drc));
}

TEST(Detect, NetpbmFamily) {
  EXPECT_EQ(detect("P5\n2 2\n255\n...."), Format::pgm);
  EXPECT_EQ(detect("P2 2 2 255 0 0 0 0"), Format::pgm);
  EXPECT_EQ(detect("P6\n1 1\n255\nabc"), Format::ppm);
  EXPECT_EQ(detect("P3\n1 1\n255\n1 2 3"), Format::ppm);
  EXPECT_EQ(detect("P7\nWIDTH 1\n"), Format::pam);
  EXPECT_EQ(detect("PF\n1 1\n-1.0\n"), Format::pfm);
  EXPECT_EQ(detect("Pf\n1 1\n-1.0\n"), Format::pfm);
}

TEST(Detect, MeshText) {
  EXPECT_EQ(detect("ply\nformat ascii 1.0\n"), Format::ply);
  EXPECT_EQ(detect("ply\r\nformat ascii 1.0\r\n"), Format::ply);
  EXPECT_EQ(detect("OFF\n3 1 0\n"), Format::off);
  EXPECT_EQ(detect("# comment\nCOFF\n"), Format::off);
  EXPECT_EQ(detect("NOFF 3 1 0"), Format::off);
  EXPECT_EQ(detect("# made by hand\nv 0 0 0\nv 1 0 0\nf 1 2 3\n"), Format::obj);
  EXPECT_EQ(detect("mtllib a.mtl\no thing\n"), Format::obj);
  EXPECT_EQ(detect("solid cube\n  facet normal 0 0 1\n"), Format::stl);
}

TEST(Detect, BinaryStlIsRecognisedByItsSizeEvenIfItSaysSolid) {
  EXPECT_EQ(detect(binary_stl(2, "solid but binary")), Format::stl);
  EXPECT_EQ(detect(binary_stl(0, "")), Format::stl);
}

TEST(Detect, VolumesDatasetsTablesJson) {
  EXPECT_EQ(detect("ObjectType = Image\nNDims = 3\n"), Format::mha);
  EXPECT_EQ(detect("Comment = made by hand\nObjectType = Image\n"), Format::mha);
  EXPECT_EQ(detect("# vtk DataFile Version 3.0\nx\nASCII\n"), Format::vtk);
  EXPECT_EQ(detect("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">"), Format::vtu);
  EXPECT_EQ(detect("<VTKFile type=\"ImageData\">"), Format::vti);
  EXPECT_EQ(detect("<VTKFile type=\"PolyData\">"), Format::vtp);
  EXPECT_EQ(detect("x,y,z\n1,2,3\n"), Format::csv);
  EXPECT_EQ(detect("x\ty\n1\t2\n"), Format::tsv);
  EXPECT_EQ(detect("  {\"a\": 1}"), Format::json);
  EXPECT_EQ(detect("[1,2]"), Format::json);
}

TEST(Detect, UnknownAndEmptyInputAreBadInput) {
  for (const std::string& s : {std::string(), std::string("hello world"), std::string("\x01\x02\x03", 3),
                              std::string("<?xml version=\"1.0\"?><svg/>")}) {
    try {
      detect(s);
      FAIL() << "accepted: " << s;
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input);
      EXPECT_NE(std::string(e.what()).find("(test)"), std::string::npos) << e.what();
    }
  }
}

TEST(Detect, NiftiPairsAnalyzeNifti2AndMgh) {
  std::string h = nifti_header(false);
  std::memcpy(h.data() + 344, "ni1\0", 4);
  EXPECT_EQ(detect(h), Format::nifti_pair);
  // Analyze 7.5: no magic, but sizeof_hdr 348, a sane dim[0] and a known datatype.
  std::memset(h.data() + 344, 0, 4);
  EXPECT_THROW(detect(h), fest::Error);  // dim[0] 0, datatype 0: nothing says Analyze
  const std::int16_t three = 3, int16_code = 4;
  std::memcpy(h.data() + 40, &three, 2);
  std::memcpy(h.data() + 70, &int16_code, 2);
  EXPECT_EQ(detect(h), Format::analyze);
  // NIfTI-2: sizeof_hdr 540 and "n+2" at byte 4.
  std::string h2(544, '\0');
  const std::int32_t size2 = 540;
  std::memcpy(h2.data(), &size2, 4);
  std::memcpy(h2.data() + 4, "n+2\0\r\n\032\n", 8);
  EXPECT_EQ(detect(h2), Format::nifti2);
  std::memcpy(h2.data() + 4, "ni2\0", 4);
  EXPECT_EQ(detect(h2), Format::nifti_pair);
  // MGH: big-endian version 1, four positive sizes, a type code and enough bytes.
  std::string m(284 + 2 * 3 * 4, '\0');
  const unsigned char head[] = {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 4, 0, 0, 0, 1, 0, 0, 0, 0};
  std::memcpy(m.data(), head, sizeof head);
  EXPECT_EQ(detect(m), Format::mgh);
  EXPECT_THROW(detect(m.substr(0, m.size() - 1)), fest::Error);  // too short for its voxels
  // MINC (netCDF, HDF5) is named in the refusal.
  for (const char* magic : {"CDF\x01", "\x89HDF\r\n\x1a\n"}) {
    try {
      detect(std::string(magic) + std::string(400, '\0'));
      FAIL();
    } catch (const fest::Error& e) {
      EXPECT_NE(std::string(e.what()).find("MINC"), std::string::npos) << e.what();
    }
  }
}

TEST(OutputFormat, FromNames) {
  using fest::formats::output_format_from_name;
  EXPECT_EQ(output_format_from_name("off").format, Format::off);
  EXPECT_EQ(output_format_from_name(".OFF").format, Format::off);
  auto nii = output_format_from_name("nii.gz");
  EXPECT_EQ(nii.format, Format::nifti);
  EXPECT_TRUE(nii.gzip);
  EXPECT_EQ(output_format_from_name("tif").format, Format::tiff);
  EXPECT_THROW(output_format_from_name("bmp"), fest::Error);
  EXPECT_THROW(output_format_from_name("gz"), fest::Error);
}

TEST(OutputFormat, FromPaths) {
  using fest::formats::output_format_from_path;
  EXPECT_EQ(output_format_from_path("dir.v2/bunny.ply").format, Format::ply);
  auto p = output_format_from_path("/tmp/head.nii.gz");
  EXPECT_EQ(p.format, Format::nifti);
  EXPECT_TRUE(p.gzip);
  EXPECT_EQ(output_format_from_path("scan.TIFF").format, Format::tiff);
  try {
    output_format_from_path("noextension");
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
  }
  EXPECT_THROW(output_format_from_path("a.docx"), fest::Error);
  EXPECT_THROW(output_format_from_path(".hidden"), fest::Error);
  // Volumes: .mgz is gzip-compressed MGH; .hdr is a NIfTI-1 pair.
  p = output_format_from_path("brain.mgz");
  EXPECT_EQ(p.format, Format::mgh);
  EXPECT_TRUE(p.gzip);
  EXPECT_EQ(output_format_from_path("brain.mgh").format, Format::mgh);
  EXPECT_EQ(output_format_from_path("pair.hdr").format, Format::nifti_pair);
  EXPECT_EQ(output_format_from_path("x.nii").format, Format::nifti);
  EXPECT_EQ(fest::formats::output_format_from_name("nifti2").format, Format::nifti2);
  EXPECT_TRUE(fest::formats::output_format_from_name("mgz").gzip);
}

TEST(OutputFormat, NamesAndKindsAgree) {
  using namespace fest::formats;
  EXPECT_EQ(kind_of(Format::drc), Kind::mesh);
  EXPECT_EQ(kind_of(Format::exr), Kind::image);
  EXPECT_EQ(kind_of(Format::mha), Kind::volume);
  EXPECT_EQ(kind_of(Format::vtk), Kind::dataset);
  EXPECT_STREQ(format_name(Format::nifti), "nifti");
  EXPECT_STREQ(format_extension(Format::nifti), ".nii");
  EXPECT_STREQ(kind_name(Kind::table), "table");
}
