// The scene JSON codec: round trip of the built-in Cornell box, transforms, and refusal of
// malformed documents with the JSON path named.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "radiosity/cornell.hpp"
#include "radiosity/scene_json.hpp"

namespace fest::radiosity {
namespace {

TEST(RadiositySceneJson, CornellRoundTrip) {
  const Scene s = cornell_box();
  const SceneFile f = decode_scene_json(encode_scene_json(s));
  ASSERT_EQ(f.scene.objects.size(), 8u);
  EXPECT_EQ(f.scene.units, "mm");
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    EXPECT_EQ(f.scene.objects[i].name, s.objects[i].name);
    EXPECT_TRUE((f.scene.objects[i].reflectance == s.objects[i].reflectance).all());
    EXPECT_EQ(f.scene.objects[i].faces, s.objects[i].faces);
    ASSERT_EQ(f.scene.objects[i].vertices.size(), s.objects[i].vertices.size());
    for (std::size_t v = 0; v < s.objects[i].vertices.size(); ++v)
      EXPECT_EQ(f.scene.objects[i].vertices[v], s.objects[i].vertices[v]);
  }
  EXPECT_NO_THROW(check_scene(f.scene));
}

TEST(RadiositySceneJson, TransformAndMeshReference) {
  const SceneFile f = decode_scene_json(R"({"objects": [
    {"name": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]], "reflectance": 0.5,
     "emission": [1,2,3], "transform": [2,0,0,1, 0,2,0,0, 0,0,2,0, 0,0,0,1]},
    {"name": "b", "mesh": "b.obj", "reflectance": [0.1, 0.2, 0.3]}]})");
  ASSERT_EQ(f.scene.objects.size(), 2u);
  EXPECT_EQ(f.scene.objects[0].vertices[1], Eigen::Vector3d(3, 0, 0));
  EXPECT_EQ(f.mesh_paths[1], "b.obj");
  EXPECT_TRUE(f.mesh_paths[0].empty());
  EXPECT_EQ(f.scene.objects[0].emission[2], 3);
}

TEST(RadiositySceneJson, MalformedDocumentsAreBadInput) {
  for (const char* text :
       {"", "[]", "{\"objects\": 3}", "{\"objects\": [{\"reflectance\": 0.5}]}",
        "{\"objects\": [{\"vertices\": [[0,0]], \"faces\": [], \"reflectance\": 0.5}]}",
        "{\"objects\": [{\"vertices\": [], \"faces\": [[-1,0,1]], \"reflectance\": 0.5}]}",
        "{\"objects\": [], \"colour\": 1}",
        "{\"objects\": [{\"mesh\": \"a.obj\", \"reflectance\": 0.5, \"texture\": \"w.png\"}]}"}) {
    try {
      decode_scene_json(text);
      ADD_FAILURE() << "accepted " << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input) << text;
    }
  }
}

}  // namespace
}  // namespace fest::radiosity
