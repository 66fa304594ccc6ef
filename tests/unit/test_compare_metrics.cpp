#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "compare/checks.hpp"
#include "compare/image_compare.hpp"
#include "compare/json_compare.hpp"
#include "compare/table_compare.hpp"
#include "compare/volume_compare.hpp"
#include "core/error.hpp"

using namespace fest::compare;

TEST(ImageError, UnitDifferenceOn8Bit) {
  cv::Mat a(4, 5, CV_8UC3, cv::Scalar(10, 20, 30)), b(4, 5, CV_8UC3, cv::Scalar(11, 20, 30));
  const auto e = image_error(a, b);
  // Channel 0 differs by 1 everywhere: RMSE 1, PSNR = 20 log10(255).
  EXPECT_DOUBLE_EQ(e.channels[0].rmse, 1.0);
  EXPECT_NEAR(e.channels[0].psnr, 20 * std::log10(255.0), 1e-12);
  EXPECT_EQ(e.channels[1].rmse, 0.0);
  EXPECT_TRUE(std::isinf(e.channels[1].psnr));
  // Over all three channels: mean square 1/3.
  EXPECT_NEAR(e.all.rmse, std::sqrt(1.0 / 3.0), 1e-12);
  EXPECT_EQ(e.all.max_abs, 1.0);
}

TEST(ImageError, NanMatchesOnlyNan) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::Mat a(1, 2, CV_32F), b(1, 2, CV_32F);
  a.at<float>(0, 0) = nan;
  b.at<float>(0, 0) = nan;
  a.at<float>(0, 1) = 1;
  b.at<float>(0, 1) = 1;
  EXPECT_EQ(image_error(a, b).all.max_abs, 0.0);
  b.at<float>(0, 1) = nan;
  EXPECT_TRUE(std::isinf(image_error(a, b).all.max_abs));
}

TEST(ImageError, ShapeMismatchIsAFailureNotACrash) {
  cv::Mat a(4, 4, CV_8UC1), b(4, 5, CV_8UC1), c(4, 4, CV_8UC3);
  EXPECT_THROW(image_error(a, b), fest::Error);
  EXPECT_THROW(image_error(a, c), fest::Error);
}

TEST(VolumeError, DicePerLabel) {
  fest::Volume a, b;
  a.type = b.type = fest::ScalarType::u8;
  a.resize(4, 1, 1);
  b.resize(4, 1, 1);
  a.voxels = {1, 1, 2, 0};
  b.voxels = {1, 2, 2, 0};
  const auto e = volume_error(a, b);
  ASSERT_TRUE(e.labels);
  // label 1: |A|=2, |B|=1, both=1 -> 2/3; label 2: |A|=1, |B|=2, both=1 -> 2/3.
  EXPECT_NEAR(e.dice.at(1), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(e.dice.at(2), 2.0 / 3.0, 1e-15);
  EXPECT_EQ(e.dice.count(0), 0u);
  EXPECT_EQ(e.max_abs, 1.0);
  EXPECT_NEAR(e.rmse, 0.5, 1e-15);
}

TEST(VolumeError, FloatVolumesHaveNoDice) {
  fest::Volume a;
  a.type = fest::ScalarType::f32;
  a.resize(2, 2, 2);
  EXPECT_FALSE(volume_error(a, a).labels);
  fest::Volume b = a;
  b.resize(2, 2, 3);
  EXPECT_THROW(volume_error(a, b), fest::Error);
}

TEST(TableError, PerColumnMaxima) {
  fest::Table a, b;
  a.add_column("x", {1, 2, 3});
  a.add_column("y", {0, 0, 4});
  b.add_column("y", {0, 0, 5});  // columns matched by name, not position
  b.add_column("x", {1, 2.5, 3});
  const auto e = table_error(a, b);
  EXPECT_EQ(e.columns[0].max_abs, 0.5);
  EXPECT_EQ(e.columns[1].max_abs, 1.0);
  EXPECT_NEAR(e.columns[1].max_rel, 0.2, 1e-15);
  EXPECT_EQ(e.max_abs, 1.0);
}

TEST(Checks, ParseAndEvaluate) {
  Check c = parse_threshold(" psnr >= 40 ");
  EXPECT_EQ(c.metric, "psnr");
  EXPECT_FALSE(c.at_most);
  EXPECT_EQ(c.limit, 40);
  EXPECT_THROW(parse_threshold("psnr=40"), fest::Error);
  EXPECT_THROW(parse_threshold("<=1"), fest::Error);
  EXPECT_THROW(parse_threshold("rmse<=abc"), fest::Error);
  // NaN and infinities mean no check at all: refused as usage errors, in words.
  for (const char* t : {"psnr>=nan", "psnr>=NaN", "psnr>=inf", "rmse<=-inf", "psnr>=1e999"}) {
    try {
      parse_threshold(t);
      ADD_FAILURE() << t << " was accepted";
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::usage) << t;
      EXPECT_NE(std::string(e.what()).find("must be a finite number"), std::string::npos) << e.what();
    }
  }

  Metrics m;
  m.set("max_abs", 0.5);
  m.set("psnr", 35);
  m.require("max_abs", "<=", 0);
  EXPECT_EQ(m.evaluate().size(), 1u);
  m.require(parse_threshold("max_abs<=1"));  // replaces the default check
  EXPECT_TRUE(m.evaluate().empty());
  m.require(parse_threshold("psnr>=40"));
  auto failures = m.evaluate();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0], "psnr = 35 is below 40");
  m.require(parse_threshold("dice>=0.9"));
  EXPECT_THROW(m.evaluate(), fest::Error);  // not measured: a usage error
}

TEST(Checks, AskedCriterionReplacesTheDefaultsOfItsFamily) {
  // The README's CI example: an image at PSNR 51 must pass 'psnr>=40' although its
  // max_abs is not 0, because psnr and max_abs measure the same error.
  Metrics m;
  m.set("max_abs", 2);
  m.set("rmse", 0.72);
  m.set("psnr", 51);
  m.set("alpha_max_abs", 0);
  m.family({"max_abs", "rmse", "psnr"});
  m.require("alpha_max_abs", "<=", 0);
  m.require("max_abs", "<=", 0);
  EXPECT_EQ(m.evaluate().size(), 1u);
  m.require(parse_threshold("psnr>=40"));
  EXPECT_TRUE(m.evaluate().empty());
  // A criterion the user asked for is not replaced by another one of its family ...
  m.require(parse_threshold("max_abs<=1"));
  m.require(parse_threshold("rmse<=1"));
  ASSERT_EQ(m.evaluate().size(), 1u);
  EXPECT_EQ(m.evaluate()[0], "max_abs = 2 exceeds 1");
  // ... and defaults outside the family stay.
  m.set("alpha_max_abs", 255);
  EXPECT_EQ(m.evaluate().size(), 2u);
  const auto checks = m.to_json()["checks"];
  ASSERT_EQ(checks.size(), 4u);
  EXPECT_TRUE(checks[0]["default"].get<bool>());   // alpha_max_abs
  EXPECT_FALSE(checks[1]["default"].get<bool>());  // psnr
}

TEST(ImageError, RgbAgainstRgbaComparesColourAndMeasuresAlphaApart) {
  cv::Mat rgb(2, 2, CV_8UC3, cv::Scalar(10, 20, 30));
  cv::Mat rgba(2, 2, CV_8UC4, cv::Scalar(10, 20, 30, 255));
  auto e = image_error(rgb, rgba);
  EXPECT_EQ(e.channels.size(), 3u);
  EXPECT_EQ(e.all.max_abs, 0);
  EXPECT_TRUE(e.alpha.measured);
  EXPECT_EQ(e.alpha.image, 2);
  EXPECT_EQ(e.alpha.max_abs, 0);
  rgba.at<cv::Vec4b>(1, 1) = cv::Vec4b(13, 20, 30, 55);  // one colour off by 3, alpha 55
  e = image_error(rgba, rgb);
  EXPECT_EQ(e.alpha.image, 1);
  EXPECT_EQ(e.all.max_abs, 3);
  EXPECT_EQ(e.alpha.max_abs, 200);
  EXPECT_EQ(e.alpha.min_alpha, 55);
  // Grey against grey + alpha, too; but two colour channels against four is a difference.
  EXPECT_TRUE(image_error(cv::Mat(2, 2, CV_8UC1, cv::Scalar(7)), cv::Mat(2, 2, CV_8UC2, cv::Scalar(7, 255))).alpha.measured);
  EXPECT_THROW(image_error(cv::Mat(2, 2, CV_8UC2), rgba), fest::Error);
  EXPECT_THROW(image_error(cv::Mat(2, 2, CV_8UC1), rgb), fest::Error);
}

TEST(Checks, NanFailsAndJsonHasNoInfinity) {
  Metrics m;
  m.set("rmse", std::nan(""));
  m.require("rmse", "<=", 1);
  EXPECT_EQ(m.evaluate().size(), 1u);
  EXPECT_TRUE(m.to_json()["metrics"]["rmse"].is_null());
  EXPECT_FALSE(m.to_json()["pass"].get<bool>());
}

TEST(JsonDifference, NumbersByValueStructureExactly) {
  const auto a = nlohmann::json::parse(R"({"x": 1, "y": [1, 2, {"z": 3}], "s": "t"})");
  const auto same_keys_reordered = nlohmann::json::parse(R"({"s": "t", "y": [1, 2, {"z": 3.5}], "x": 1})");
  auto d = json_difference(a, same_keys_reordered);
  EXPECT_EQ(d.max_abs, 0.5);
  EXPECT_EQ(d.numbers, 4u);
  EXPECT_EQ(d.structural, 0u);

  d = json_difference(a, nlohmann::json::parse(R"({"x": "1", "y": [1, 2], "s": "t", "extra": null})"));
  // "x" changes kind, "y" loses an element, "extra" is new: three structural differences.
  EXPECT_EQ(d.structural, 3u);
  EXPECT_EQ(d.first_structural_path, "/x");
}
