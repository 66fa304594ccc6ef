// Inputs that once got past brdffit's JSON decoders (tests/data/regress/brdffit/, found
// for fuzz_brdffit_json; named for what they exercise): a JSON library exception escaping,
// a double too large for an int (undefined behaviour), a width of 2^32 + 1 read as 1.
// Each must now fail with one bad_input error. rig_* go to the rig decoder, camera_* to
// cam.json's, materials_* to the materials file's (against a two-triangle square).
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdffit/ltw_format.hpp"
#include "brdffit/rig_json.hpp"
#include "expect_error.hpp"
#include "reflectance/view_json.hpp"
#include "scene_io.hpp"
#include "testdata.hpp"

TEST(BrdffitRegress, FuzzFindingsAreBadInput) {
  fest::reflectance::TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  fest::reflectance::compute_vertex_normals(square);
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/brdffit"))) {
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const auto doc = nlohmann::json::parse(fest::test::slurp(entry.path().string()));
    fest::test::expect_bad_input([&] {
      if (name.rfind("rig_", 0) == 0) fest::brdffit::decode_rig(doc, "rig.json");
      else if (name.rfind("camera_", 0) == 0) fest::reflectance::camera_from_json(doc, "cam.json");
      else fest::brdffit_tool::materials_from_json(doc, square, "materials.json");
    });
    ++replayed;
  }
  EXPECT_GE(replayed, 8);
}

// .ltw files that fuzz_ltw found (tests/data/regress/brdffit_ltw/): a header count of
// 1.2e31 once reached a float-to-size_t cast (undefined; now lib/core/json_value.hpp).
TEST(BrdffitRegress, LtwFuzzFindingsAreBadInput) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/brdffit_ltw"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = fest::test::slurp(entry.path().string());
    fest::test::expect_bad_input([&] { fest::brdffit::decode_ltw(bytes); });
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}
