// lib/core bitmap_font and volume_view: the font's glyphs, the scale bar's round lengths,
// the window, and the letters of a volume whose voxel axes are permuted and flipped.
#include <gtest/gtest.h>

#include <set>

#include "core/bitmap_font.hpp"
#include "core/error.hpp"
#include "core/volume_view.hpp"

namespace {

TEST(BitmapFont, GlyphsDifferAndUnknownIsQuestionMark) {
  const std::string chars = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZmx-+.,:=/()%_?";
  std::set<std::array<unsigned char, 7>> seen;
  for (char c : chars) seen.insert(fest::glyph_rows(c));
  EXPECT_EQ(seen.size(), chars.size());  // no two characters look alike
  EXPECT_EQ(fest::glyph_rows('#'), fest::glyph_rows('?'));
  EXPECT_EQ(fest::glyph_rows('a'), fest::glyph_rows('A'));  // lowercase drawn as capitals
  EXPECT_EQ(fest::text_width("ABC", 2), 3 * 6 * 2 - 2);
}

TEST(BitmapFont, DrawsInsideAndClipsOutside) {
  cv::Mat img(10, 10, CV_8UC3, cv::Scalar(0, 0, 0));
  fest::draw_text(img, 0, 0, "L", cv::Scalar(255, 0, 0));
  // 'L': the left column of 7 pixels and the bottom row of 5.
  EXPECT_EQ(cv::countNonZero(img.reshape(1) > 0), 7 + 4);
  fest::draw_text(img, 8, 8, "WWW", cv::Scalar(255, 255, 255));  // runs off the edge
}

TEST(VolumeView, RoundScaleLengths) {
  EXPECT_DOUBLE_EQ(fest::round_scale_length(55), 50);
  EXPECT_DOUBLE_EQ(fest::round_scale_length(50), 50);
  EXPECT_DOUBLE_EQ(fest::round_scale_length(49), 20);
  EXPECT_DOUBLE_EQ(fest::round_scale_length(12), 10);
  EXPECT_DOUBLE_EQ(fest::round_scale_length(3), 2);
  EXPECT_DOUBLE_EQ(fest::round_scale_length(0.7), 0.5);
  EXPECT_EQ(fest::round_scale_length(0), 0);
}

fest::Volume box(std::size_t nx, std::size_t ny, std::size_t nz) {
  fest::Volume v;
  v.resize(nx, ny, nz);
  return v;
}

TEST(VolumeView, WindowIsPercentilesOfNonZeroVoxels) {
  fest::Volume v = box(10, 10, 1);
  for (std::size_t i = 0; i < 100; ++i) v.voxels[i] = i < 50 ? 0.0 : double(i - 49);  // 1..50 and zeros
  const auto w = fest::robust_window(v);
  EXPECT_DOUBLE_EQ(w[0], 1);   // floor(0.01 * 49) = 0th of 1..50
  EXPECT_DOUBLE_EQ(w[1], 49);  // floor(0.99 * 49) = 48th
  fest::Volume c = box(2, 2, 2);
  for (double& x : c.voxels) x = 7;
  EXPECT_EQ(fest::robust_window(c), (std::array<double, 2>{0, 7}));
}

TEST(VolumeView, LettersFollowTheDirections) {
  // Voxel axis i points Left, j Inferior, k Anterior (an LIA volume), 2 x 1 x 3 mm.
  fest::Volume v = box(20, 30, 10);
  v.spacing = {2, 1, 3};
  v.direction = {-1, 0, 0, /**/ 0, 0, 1, /**/ 0, -1, 0};
  fest::VolumeViewOptions o;
  o.pixel_mm = 1;
  const fest::VolumeView view = fest::render_volume_view(v, o);
  ASSERT_EQ(view.panels.size(), 3u);
  const fest::ViewPanel& axial = view.panels[0];
  EXPECT_EQ(axial.left + axial.right + axial.top + axial.bottom, "LRAP");
  EXPECT_EQ(axial.width, 40);   // L-R: 20 voxels of 2 mm
  EXPECT_EQ(axial.height, 30);  // A-P: 10 voxels of 3 mm
  const fest::ViewPanel& sagittal = view.panels[2];
  EXPECT_EQ(sagittal.left + sagittal.right + sagittal.top + sagittal.bottom, "PASI");
  EXPECT_EQ(sagittal.height, 30);  // S-I: 30 voxels of 1 mm
  EXPECT_DOUBLE_EQ(view.obliquity_deg, 0);
  o.convention = fest::DisplayConvention::radiological;
  const fest::VolumeView rad = fest::render_volume_view(v, o);
  EXPECT_EQ(rad.panels[0].left + rad.panels[0].right, "RL");
  o.slice = std::array<std::size_t, 3>{20, 0, 0};
  EXPECT_THROW(fest::render_volume_view(v, o), fest::Error);
}

}  // namespace
