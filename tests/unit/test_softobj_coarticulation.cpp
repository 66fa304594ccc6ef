// softobj coarticulation (docs/softobj.md §5): key times and values from rules 1-4 by
// hand, and the interpolation against the Hermite formula evaluated here.
#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "softobj/coarticulation.hpp"

using namespace fest::softobj;

namespace {

const char* kTable = R"({"phonemes": {
  "i": {"class": "vowel", "tongue": {"a1": 40, "l1": 14}},
  "A": {"class": "vowel", "tongue": {"a1": -6, "l1": 16}},
  "@": {"class": "vowel", "deformable": true, "tongue": {"a1": 10, "l1": 15}},
  "b": {"class": "consonant", "tongue": null}},
  "max_speed": {"length": 1000, "angle": 600}, "lag_s": {"tip": 0, "middle": 0, "back": 0}})";

constexpr int A1 = 12, L1 = 3;

}  // namespace

TEST(SoftobjCoarticulation, NullPhonemeAnticipatesFromItsStart) {
  const PhonemeTable t = decode_phoneme_table(kTable);
  // /b i b/: the first /b/ takes /i/'s target at its start 0; /i/ keys at its midpoint 0.2;
  // the last /b/ has no later target and holds /i/'s, keyed at its start 0.3.
  const auto tl = decode_timeline("b 0 0.1\ni 0.1 0.3\nb 0.3 0.4\n", t);
  const auto keys = key_frames(tl, t);
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_DOUBLE_EQ(keys[0].time, 0.0);
  EXPECT_DOUBLE_EQ(keys[1].time, 0.2);
  EXPECT_DOUBLE_EQ(keys[2].time, 0.3);
  for (const auto& k : keys) EXPECT_DOUBLE_EQ(k.params[A1], 40);
}

TEST(SoftobjCoarticulation, DeformableBlendsAndSpeedLimitsLengthsOnly) {
  PhonemeTable t = decode_phoneme_table(kTable);
  const auto tl = decode_timeline("i 0 0.2\n@ 0.2 0.4\nA 0.4 0.6\n", t);
  auto keys = key_frames(tl, t);
  ASSERT_EQ(keys.size(), 3u);
  // rule 3: 0.5 * 10 + 0.25 * (40 - 6) = 13.5
  EXPECT_DOUBLE_EQ(keys[1].params[A1], 13.5);
  // rule 4 with 5 mm/s: from l1 = 14 over 0.2 s at most 1 mm; the schwa's blended 15 is
  // reachable (+1), /A/'s 16 from 15 likewise; angles unchanged.
  t.max_speed_length = 2.5;  // 0.5 mm per 0.2 s
  keys = key_frames(tl, t);
  EXPECT_DOUBLE_EQ(keys[1].params[L1], 14.5);
  EXPECT_DOUBLE_EQ(keys[2].params[L1], 15.0);
  EXPECT_DOUBLE_EQ(keys[2].params[A1], -6);
}

TEST(SoftobjCoarticulation, HermiteWithCatmullRomTangents) {
  const PhonemeTable t = decode_phoneme_table(kTable);
  const auto keys = key_frames(decode_timeline("i 0 0.2\nA 0.2 0.4\ni 0.4 0.6\n", t), t);
  // keys at 0.1 (40), 0.3 (-6), 0.5 (40); at t = 0.2 (s = 0.5, h = 0.2): tangents
  // m0 = (-6 - 40)/0.2 = -230 (one-sided), m1 = (40 - 40)/0.4 = 0.
  const double h = 0.2, s = 0.5;
  const double expected = (2 * s * s * s - 3 * s * s + 1) * 40 + (s * s * s - 2 * s * s + s) * h * -230 +
                          (-2 * s * s * s + 3 * s * s) * -6 + (s * s * s - s * s) * h * 0;
  EXPECT_NEAR(params_at(keys, t, 0.2)[A1], expected, 1e-12);
  EXPECT_DOUBLE_EQ(params_at(keys, t, 0.0)[A1], 40);  // before the first key: held
  EXPECT_DOUBLE_EQ(params_at(keys, t, 0.3)[A1], -6);  // at a key: its value
}

TEST(SoftobjCoarticulation, BadInput) {
  const PhonemeTable t = decode_phoneme_table(kTable);
  EXPECT_THROW(decode_timeline("x 0 1\n", t), fest::Error);        // unknown phoneme
  EXPECT_THROW(decode_timeline("i 0.5 0.2\n", t), fest::Error);    // end before start
  EXPECT_THROW(decode_timeline("i 0 0.5\nA 0.3 0.6\n", t), fest::Error);  // overlap
  EXPECT_THROW(decode_timeline("i zero 1\n", t), fest::Error);
  EXPECT_THROW(decode_timeline("", t), fest::Error);
  EXPECT_THROW(decode_phoneme_table("{\"phonemes\": {\"i\": {\"tongue\": {\"q\": 1}}}}"), fest::Error);
  EXPECT_THROW(decode_phoneme_table("[1]"), fest::Error);
}
