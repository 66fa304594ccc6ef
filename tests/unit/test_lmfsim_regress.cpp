// Inputs that once broke lmfsim's scene codec under fuzz_lmfsim_scene (tests/data/regress/
// lmfsim/, named for what they exercise; a JSON library exception escaped): each must now
// fail with one bad_input error.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "expect_error.hpp"
#include "lmfsim/scene_json.hpp"
#include "testdata.hpp"

TEST(LmfsimRegress, FuzzFindingsAreBadInput) {
  const fest::lmfsim::MeshLoader no_meshes = [](const std::string& path, auto&, auto&) {
    throw fest::bad_input("no meshes here ({})", path);
  };
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/lmfsim"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const auto doc = nlohmann::json::parse(fest::test::slurp(entry.path().string()));
    fest::test::expect_bad_input([&] { fest::lmfsim::scene_from_json(doc, no_meshes); });
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}
