// read_mesh(Input): the files a scene refers to are found beside the scene's path, and a
// scene on standard input (no folder) fails naming the file. The fixture glTF keeps its
// quad in quad.bin (tests/data/mesh/README.md): 4 vertices, 2 triangles. Needs the assimp
// plugin beside the test executable (built with fest when libassimp-dev is present).
#include <string>

#include "formats/input.hpp"
#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

// The plugin is missing (no libassimp-dev at configure time): status io, naming the
// package; a buffer not found is status io too, naming the file.
bool plugin_missing(const Error& e) {
  return e.status() == Status::io && std::string(e.what()).find("libassimp5") != std::string::npos;
}

TEST(MeshSceneFiles, ExternalBufferIsReadBesideThePath) {
  const formats::Input in = formats::load_input(fixture("mesh/external_buffer/quad.gltf"));
  try {
    const Mesh m = formats::parse(in, formats::read_mesh);
    EXPECT_EQ(m.n_vertices(), 4u);
    EXPECT_EQ(m.n_faces(), 2u);
    EXPECT_EQ(m.point(Mesh::VertexHandle(2)), Mesh::Point(13, 22, 30));  // (3,2,0) moved by (10,20,30)
  } catch (const Error& e) {
    if (plugin_missing(e)) GTEST_SKIP() << e.what();
    throw;
  }
}

TEST(MeshSceneFiles, StandardInputNamesTheBufferItCannotFind) {
  const formats::Input in = formats::recognise(slurp(fixture("mesh/external_buffer/quad.gltf")), "-");
  try {
    formats::parse(in, formats::read_mesh);
    FAIL() << "a glTF with an external buffer was read from standard input";
  } catch (const Error& e) {
    if (plugin_missing(e)) GTEST_SKIP() << e.what();
    EXPECT_EQ(e.status(), Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("\"quad.bin\""), std::string::npos) << e.what();
  }
  // Bytes without an Input have no folder either.
  EXPECT_THROW(formats::read_mesh(in.bytes, in.format), Error);
}

}  // namespace
}  // namespace fest::test
