// The .ltx file: exact round trip, and every malformed file rejected with bad_input.

#include <gtest/gtest.h>

#include "brdffit/ltx_format.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::brdffit;

LumitexelSet example() {
  LumitexelSet s;
  s.mesh_sha256 = "ab12";
  s.images = {"hdr/a000_L0.exr", "hdr/a001_L0.exr"};
  for (int i = 0; i < 3; ++i) {
    Lumitexel l;
    l.p = Eigen::Vector3f(0.1f * i, -2.5f, 1e-7f);
    l.n = Eigen::Vector3f(0, 0.6f, 0.8f);
    l.triangle = 70000u + static_cast<std::uint32_t>(i);
    l.home_image = static_cast<std::uint16_t>(i % 2);
    l.home_pixel = Eigen::Vector2f(3.0f + i, 4.5f);
    l.first_sample = static_cast<std::uint64_t>(2 * i);
    l.count = 2;
    s.lumitexels.push_back(l);
  }
  for (int k = 0; k < 6; ++k) {
    Sample x;
    x.image = static_cast<std::uint16_t>(k % 2);
    x.u_world = Eigen::Vector3f(0, 0, 1);
    x.v_world = Eigen::Vector3f(0.6f, 0, 0.8f);
    x.r = Eigen::Vector3f(0.25f * k, 1.0f / 3, 1e30f);
    x.weight = 0.5f;
    s.samples.push_back(x);
  }
  return s;
}

void expect_bad(const std::vector<std::uint8_t>& bytes) {
  try {
    decode_ltx(bytes, nullptr);
    FAIL() << "accepted";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input) << e.what();
  }
}

}  // namespace

TEST(Ltx, RoundTripIsExact) {
  const LumitexelSet s = example();
  const auto bytes = encode_ltx(s, {{"cameras", {1, 2}}, {"lumitexels", 999}});
  ASSERT_EQ(std::string(bytes.begin(), bytes.begin() + 8), "LUMITEX1");
  nlohmann::json h;
  const LumitexelSet t = decode_ltx(bytes, &h);
  EXPECT_EQ(h["lumitexels"], 3);  // the set wins over the caller's header
  EXPECT_EQ(h["cameras"], nlohmann::json({1, 2}));
  EXPECT_EQ(t.mesh_sha256, s.mesh_sha256);
  EXPECT_EQ(t.images, s.images);
  ASSERT_EQ(t.lumitexels.size(), 3u);
  ASSERT_EQ(t.samples.size(), 6u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(t.lumitexels[i].p, s.lumitexels[i].p);
    EXPECT_EQ(t.lumitexels[i].n, s.lumitexels[i].n);
    EXPECT_EQ(t.lumitexels[i].triangle, s.lumitexels[i].triangle);
    EXPECT_EQ(t.lumitexels[i].home_image, s.lumitexels[i].home_image);
    EXPECT_EQ(t.lumitexels[i].home_pixel, s.lumitexels[i].home_pixel);
    EXPECT_EQ(t.lumitexels[i].first_sample, s.lumitexels[i].first_sample);
    EXPECT_EQ(t.lumitexels[i].count, s.lumitexels[i].count);
  }
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(t.samples[k].image, s.samples[k].image);
    EXPECT_EQ(t.samples[k].u_world, s.samples[k].u_world);
    EXPECT_EQ(t.samples[k].v_world, s.samples[k].v_world);
    EXPECT_EQ(t.samples[k].r, s.samples[k].r);
    EXPECT_EQ(t.samples[k].weight, s.samples[k].weight);
  }
  // Sizes as ltx(5) lays them out: 12 + header + 48 N + 42 M.
  const std::uint32_t hlen = bytes[8] | bytes[9] << 8 | bytes[10] << 16 | static_cast<std::uint32_t>(bytes[11]) << 24;
  EXPECT_EQ(bytes.size(), 12 + hlen + 48 * 3 + 42 * 6);
}

TEST(Ltx, MalformedFilesAreBadInput) {
  const auto good = encode_ltx(example(), {});
  auto wrong_magic = good;
  wrong_magic[0] = 'X';
  expect_bad(wrong_magic);
  expect_bad(std::vector<std::uint8_t>(good.begin(), good.end() - 1));  // truncated samples
  auto longer = good;
  longer.push_back(0);
  expect_bad(longer);
  auto huge_header = good;
  huge_header[11] = 0x7f;
  expect_bad(huge_header);
  expect_bad({});
  // A lumitexel whose samples run past the sample array.
  LumitexelSet s = example();
  s.lumitexels[2].count = 3;
  EXPECT_THROW(encode_ltx(s, {}), fest::Error);
  auto bytes = encode_ltx(example(), {});
  const std::uint32_t hlen = bytes[8] | bytes[9] << 8 | bytes[10] << 16 | static_cast<std::uint32_t>(bytes[11]) << 24;
  bytes[12 + hlen + 2 * 48 + 46] = 9;  // count of lumitexel 2 := 9
  expect_bad(bytes);
}
