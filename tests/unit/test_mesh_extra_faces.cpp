// Faces OpenMesh cannot hold are kept aside, not lost (mesh_io.hpp): readers list them in
// skipped_face_list(), and the PLY/OFF/OBJ writers append extra_faces(), which is how
// ebdecode writes non-manifold meshes exactly.
#include <gtest/gtest.h>

#include "formats/mesh/mesh_io.hpp"

namespace {

using namespace fest;
using formats::Format;

// Three triangles on the edge 0-1 (a "fin"): OpenMesh takes two, the third is skipped.
constexpr const char* fin = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";

TEST(MeshExtraFaces, SkippedFacesAreListedInFileOrder) {
  const Mesh m = formats::read_mesh(fin, Format::off);
  EXPECT_EQ(m.n_faces() + formats::skipped_faces(m), 3u);
  const auto skipped = formats::skipped_face_list(m);
  ASSERT_EQ(skipped.size(), formats::skipped_faces(m));
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0], (std::vector<int>{0, 1, 4}));
}

TEST(MeshExtraFaces, WritersAppendExtraFaces) {
  Mesh m = formats::read_mesh(fin, Format::off);
  formats::set_extra_faces(m, formats::skipped_face_list(m));
  for (Format f : {Format::ply, Format::off, Format::obj}) {
    const Mesh back = formats::read_mesh(formats::write_mesh(m, f), f);
    EXPECT_EQ(back.n_faces() + formats::skipped_faces(back), 3u) << formats::format_name(f);
    EXPECT_EQ(formats::skipped_face_list(back), formats::skipped_face_list(m)) << formats::format_name(f);
  }
  formats::MeshWriteOptions ascii;
  ascii.ascii = true;
  const Mesh back = formats::read_mesh(formats::write_mesh(m, Format::ply, ascii), Format::ply);
  EXPECT_EQ(back.n_faces() + formats::skipped_faces(back), 3u);
}

}  // namespace
