// Every malformed input must give fest::Error with Status::bad_input: never a crash, a
// hang or a huge allocation. Also replays the fuzzer's finds in tests/data/regress/mesh.

#include <dirent.h>

#include <cstring>

#include "formats/mesh/attributed_ply.hpp"
#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::Format;

void expect_rejected(Format format, const std::string& bytes, const std::string& what) {
  expect_bad_input([&] { formats::read_mesh(bytes, format); }, what);
}

const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string ply_body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(MeshMalformed, EmptyInputInEveryFormat) {
  for (Format f : {Format::ply, Format::obj, Format::off, Format::stl, Format::drc})
    expect_rejected(f, "", formats::format_name(f));
}

TEST(MeshMalformed, NotAMeshFormat) {
  expect_bad_input([] { formats::read_mesh("P5\n1 1\n255\n\0", Format::pgm); }, "pgm");
}

TEST(MeshMalformed, PlyHeaders) {
  ASSERT_NO_THROW(formats::read_mesh(ply_head + ply_body, Format::ply));  // the baseline is fine
  expect_rejected(Format::ply, "plx\n" + ply_head.substr(4) + ply_body, "wrong magic");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "truncated header");
  expect_rejected(Format::ply, "ply", "magic only");
  expect_rejected(Format::ply, "ply\nformat utf16 1.0\nend_header\n", "unknown format");
  expect_rejected(Format::ply, "ply\nelement vertex 0\nend_header\n", "no format line");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property before element");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n",
                  "unknown type");
  expect_rejected(Format::ply,
                  "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n3 0 1 2\n",
                  "float list length");
  expect_rejected(Format::ply,
                  "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n3 0 1 "
                  "2\n",
                  "float vertex indices");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nend_header\n0\n",
                  "vertex without x");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nelement vertex\nend_header\n", "count missing");
  expect_rejected(Format::ply, "ply\nformat ascii 1.0\nelement vertex one\nend_header\n", "count not a number");
  expect_rejected(Format::ply, std::string("ply\nformat ascii 1.0\n\xff\xfe\x00garbage", 27), "garbage after magic");
}

TEST(MeshMalformed, PlyCounts) {
  auto with_count = [](const std::string& count) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + count +
           "\nproperty float x\nproperty float y\nproperty float z\nend_header\n" + std::string(36, '\0');
  };
  ASSERT_NO_THROW(formats::read_mesh(with_count("3"), Format::ply));
  expect_rejected(Format::ply, with_count("99999999999"), "absurd count");
  expect_rejected(Format::ply, with_count("18446744073709551615"), "uint64 max");
  expect_rejected(Format::ply, with_count("18446744073709551616"), "beyond uint64");
  expect_rejected(Format::ply, with_count("-3"), "negative count");
  expect_rejected(Format::ply, with_count("1e12"), "count in exponent form");
  expect_rejected(Format::ply, with_count("nan"), "NaN count");
  expect_rejected(Format::ply, with_count("4"), "count one too many");
  expect_rejected(Format::ply, with_count("2"), "binary body too long");
  std::string ascii = ply_head;
  ascii.replace(ascii.find("vertex 3"), 8, "vertex 99999999999");
  expect_rejected(Format::ply, ascii + ply_body, "ascii absurd count");
  // An element with no properties takes no bytes, so no body can bound its count: refused
  // whatever the encoding (fuzz_radiosity_scene spent 38 s per input on 6.7e12 of them).
  for (const char* encoding : {"ascii", "binary_little_endian"}) {
    const std::string propertyless = std::string("ply\nformat ") + encoding + " 1.0\nelement vertex 6666666666666\nend_header\n";
    expect_rejected(Format::ply, propertyless, std::string("propertyless element, ") + encoding);
    expect_bad_input([&] { formats::read_attributed_ply(propertyless); }, "attributed reader");
  }
  // With no instances it holds nothing and is harmless.
  ASSERT_NO_THROW(formats::read_mesh("ply\nformat ascii 1.0\nelement empty 0\n" + ply_head.substr(ply_head.find("element vertex")) + ply_body, Format::ply));
}

TEST(MeshMalformed, PlyBodies) {
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 0 0\n", "truncated ascii body");
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "face index out of range");
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "negative face index");
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", "list longer than the file");
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "non-number");
  expect_rejected(Format::ply, ply_head + ply_body + "junk\n", "data after the last element");
  expect_rejected(Format::ply, ply_head + "0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n", "fractional list length");

  // Binary: a face list whose uint length claims 4 billion indices.
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement face 1\n"
                       "property list uint int vertex_indices\nend_header\n";
  expect_rejected(Format::ply, binary + std::string("\xff\xff\xff\xff", 4) + std::string(12, '\0'), "huge list");
  // Valid binary triangle, then truncated by one byte.
  std::string valid = formats::write_mesh(attributed_tetrahedron(), Format::ply);
  ASSERT_NO_THROW(formats::read_mesh(valid, Format::ply));
  expect_rejected(Format::ply, valid.substr(0, valid.size() - 1), "truncated binary body");
  expect_rejected(Format::ply, valid.substr(0, valid.find("end_header") + 11 + 5), "binary body cut short");
  expect_rejected(Format::ply, valid + "x", "binary body with a trailing byte");
}

TEST(MeshMalformed, Off) {
  const std::string good = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  ASSERT_NO_THROW(formats::read_mesh(good, Format::off));
  expect_rejected(Format::off, "OFX\n3 1 0\n", "wrong magic");
  expect_rejected(Format::off, "OFF\n", "no counts");
  expect_rejected(Format::off, "OFF\n3\n", "one count");
  expect_rejected(Format::off, "OFF\n-3 1 0\n0 0 0\n", "negative count");
  expect_rejected(Format::off, "OFF\n99999999999 1 0\n0 0 0\n", "absurd count");
  expect_rejected(Format::off, "OFF\n3 99999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "face count beyond the bytes");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n", "truncated vertices");
  expect_rejected(Format::off, "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "truncated faces");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "face index out of range");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "negative face index");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n5 0 1 2\n", "face shorter than its count");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "non-number");
  expect_rejected(Format::off, "OFF\n3 1 0\n0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "vertex with two values");
  expect_rejected(Format::off, "COFF\n3 1 0\n0 0 0 1 1\n1 0 0 1 1\n0 1 0 1 1\n3 0 1 2\n", "COFF two colours");
  expect_rejected(Format::off, "4OFF\n1 0 0\n0 0 0 1\n", "4D");
  expect_rejected(Format::off, "OFF BINARY\n" + std::string(12, '\0'), "binary OFF");
  expect_rejected(Format::off, "OFF\n\x01\x02\x03\xff garbage\n", "garbage after magic");
}

TEST(MeshMalformed, Obj) {
  ASSERT_NO_THROW(formats::read_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::obj));
  expect_rejected(Format::obj, "# nothing here\n", "no vertices");
  expect_rejected(Format::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "index 0");
  expect_rejected(Format::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "index out of range");
  expect_rejected(Format::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "relative index before the start");
  expect_rejected(Format::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/5 2/5 3/5\n", "texcoord out of range");
  expect_rejected(Format::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", "normal out of range");
  expect_rejected(Format::obj, "v 0 0\n", "vertex with two numbers");
  expect_rejected(Format::obj, "v a b c\n", "non-numbers");
  expect_rejected(Format::obj, "v 0 0 0\nf 1 x 1\n", "non-integer index");
  expect_rejected(Format::obj, "v 0 0 0\nf 99999999999999999999 1 1\n", "index beyond int64");
  expect_rejected(Format::obj, std::string("\x7f\x45\x4c\x46\x02\x01\x01\x00", 8), "binary garbage");
}

TEST(MeshMalformed, Stl) {
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  ASSERT_NO_THROW(formats::read_mesh("solid t\n" + facet + "endsolid t\n", Format::stl));
  expect_rejected(Format::stl, "solid t\n" + facet, "no endsolid");
  expect_rejected(Format::stl, "solid t\n" + facet.substr(0, 40), "truncated facet");
  expect_rejected(Format::stl, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nvertex 1 0 0\n", "short vertex");
  expect_rejected(Format::stl, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\nendfacet\nendsolid\n",
                  "facet with one vertex");
  expect_rejected(Format::stl, "solid t\nbanana\nendsolid\n", "unknown keyword");
  expect_rejected(Format::stl, "solid t\n" + facet + "endsolid t\ngarbage", "garbage after endsolid");

  // Binary: 84-byte header saying one triangle, without the triangle.
  std::string header(80, ' ');
  auto with_count = [&](std::uint32_t n, std::size_t body) {
    std::string bytes = header;
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
    return bytes + std::string(body, '\0');
  };
  ASSERT_NO_THROW(formats::read_mesh(with_count(1, 50), Format::stl));
  expect_rejected(Format::stl, with_count(1, 0), "n too large");
  expect_rejected(Format::stl, with_count(0xffffffffu, 100), "n absurd");
  expect_rejected(Format::stl, with_count(2, 50), "truncated body");
  expect_rejected(Format::stl, with_count(1, 51), "one byte extra");
  expect_rejected(Format::stl, std::string(50, '\xff'), "shorter than the header");
}

TEST(MeshMalformed, Draco) {
  const std::string valid = formats::write_mesh(attributed_tetrahedron(), Format::drc);
  ASSERT_NO_THROW(formats::read_mesh(valid, Format::drc));
  expect_rejected(Format::drc, "DRACO", "magic only");
  expect_rejected(Format::drc, "DRACO" + std::string(40, '\xa5'), "garbage after magic");
  expect_rejected(Format::drc, "DRICO" + valid.substr(5), "wrong magic");
  expect_rejected(Format::drc, std::string(64, '\0'), "zeros");
  for (std::size_t cut : {6u, 11u, 20u, 40u}) {
    if (cut < valid.size()) expect_rejected(Format::drc, valid.substr(0, cut), "truncated at " + std::to_string(cut));
  }
  // Flipped bytes anywhere: success or bad_input, never a crash.
  for (std::size_t i = 5; i < valid.size(); ++i) {
    std::string bent = valid;
    bent[i] = static_cast<char>(bent[i] ^ 0x5a);
    try {
      formats::read_mesh(bent, Format::drc);
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input) << e.what();
    }
  }
}

TEST(MeshMalformed, FuzzerRegressionsAreHandled) {
  const std::string dir = fixture("regress/mesh");
  DIR* handle = opendir(dir.c_str());
  if (handle == nullptr) GTEST_SKIP() << "no " << dir;
  std::size_t files = 0;
  while (dirent* entry = readdir(handle)) {
    if (entry->d_name[0] == '.' || std::strcmp(entry->d_name, "README.md") == 0) continue;
    ++files;
    const std::string bytes = slurp(dir + "/" + entry->d_name);
    for (Format f : {Format::ply, Format::obj, Format::off, Format::stl, Format::drc}) {
      try {
        Mesh mesh = formats::read_mesh(bytes, f);
        formats::write_mesh(mesh, f);
      } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::bad_input) << entry->d_name << ": " << e.what();
      }
    }
  }
  closedir(handle);
  SUCCEED() << files << " regression inputs";
}

}  // namespace
}  // namespace fest::test
