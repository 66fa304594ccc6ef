// softobj's JSON decoders on inputs kept in tests/data/regress/softobj/: a number beyond
// double's range is nlohmann's out_of_range, not its parse_error, and once escaped the
// skeleton, phoneme-table and palate readers. Each must now give one bad_input error.
#include <filesystem>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "softobj/coarticulation.hpp"
#include "softobj/palate.hpp"
#include "softobj/skeleton_json.hpp"
#include "testdata.hpp"

TEST(SoftobjRegress, NumberOverflowIsBadInput) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/softobj"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string text = fest::test::slurp(entry.path().string());
    fest::test::expect_bad_input([&] { fest::softobj::decode_skeleton(text); }, "skeleton JSON");
    fest::test::expect_bad_input([&] { fest::softobj::decode_phoneme_table(text); }, "phoneme table");
    fest::test::expect_bad_input([&] { fest::softobj::decode_palate(text); }, "palate");
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}
