// Texture tiles (docs/terrainlod.md §3-4, terrainlod-pyramid(5)): the leaf canvas, the per-level box
// filter, the cut into tiles, the placement rules of an image on a DEM, the hillshade,
// and the texture that closing-only tiles are drawn with. Expected values come from the
// definitions (lattice-aligned copies, rounded 2 x 2 means, linear ramps that bilinear
// interpolation reproduces), never from the code's own output.

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/extract.hpp"
#include "terrainlod/texture_pyramid.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;

cv::Mat pattern(int w, int h) {  // RGB, pixel (c, r) = (3c + 5r, c r, 7c) mod 256
  cv::Mat m(h, w, CV_8UC3);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) m.at<cv::Vec3b>(r, c) = cv::Vec3b((3 * c + 5 * r) % 256, (c * r) % 256, (7 * c) % 256);
  return m;
}

TEST(TerrainTexture, HalvingIsTheRoundedMeanOfEachTwoByTwoBlock) {
  cv::Mat m(2, 4, CV_8UC1);
  const unsigned char v[8] = {0, 1, 10, 20, 1, 1, 30, 41};
  for (int k = 0; k < 8; ++k) m.at<unsigned char>(k / 4, k % 4) = v[k];
  const cv::Mat h = halve_canvas(m);
  ASSERT_EQ(h.rows, 1);
  ASSERT_EQ(h.cols, 2);
  EXPECT_EQ(h.at<unsigned char>(0, 0), 1);   // (0 + 1 + 1 + 1) / 4 = 0.75 -> 1
  EXPECT_EQ(h.at<unsigned char>(0, 1), 25);  // (10 + 20 + 30 + 41) / 4 = 25.25 -> 25
  cv::Mat half(2, 2, CV_8UC1, cv::Scalar(0));
  half.at<unsigned char>(0, 0) = 2;  // 2 / 4 = 0.5 rounds up
  EXPECT_EQ(halve_canvas(half).at<unsigned char>(0, 0), 1);
}

TEST(TerrainTexture, ALatticeAlignedImageIsTheCanvasExactly) {
  // W = H = 9 samples (8 cells), B = 4, T = 8: L = 1, canvas 16 texels = 8 cells x 2.
  TextureLayout lay{1, 4, 8, 9, 9};
  const cv::Mat img = pattern(16, 16);
  ASSERT_EQ(place_image(16, 16, 9, 9), ImagePlacement::extent);
  const cv::Mat canvas = leaf_canvas(img, ImagePlacement::extent, lay);
  ASSERT_EQ(canvas.rows, 16);
  EXPECT_EQ(cv::norm(canvas, img, cv::NORM_INF), 0);
  // Tile (1, 1, 0): east column, south row = the lower right quarter of the image.
  const cv::Mat t = tile_texture(canvas, 1, 1, 0, 8);
  EXPECT_EQ(cv::norm(t, img(cv::Rect(8, 8, 8, 8)), cv::NORM_INF), 0);
}

TEST(TerrainTexture, PaddingReplicatesTheImageEdges) {
  // 7 x 5 samples (6 x 4 cells), B = 4, T = 8: L = 1, canvas 16; the image is 12 x 8.
  TextureLayout lay{1, 4, 8, 7, 5};
  const cv::Mat img = pattern(12, 8);
  const cv::Mat canvas = leaf_canvas(img, ImagePlacement::extent, lay);
  ASSERT_EQ(canvas.rows, 16);
  // The image sits in the south-west corner (canvas rows 8..15, columns 0..11).
  EXPECT_EQ(cv::norm(canvas(cv::Rect(0, 8, 12, 8)), img, cv::NORM_INF), 0);
  for (int r = 0; r < 16; ++r)
    for (int c = 0; c < 16; ++c) {
      const int ir = std::max(0, r - 8), ic = std::min(c, 11);
      ASSERT_EQ(canvas.at<cv::Vec3b>(r, c), img.at<cv::Vec3b>(ir, ic)) << r << "," << c;
    }
}

TEST(TerrainTexture, ResamplingReproducesALinearRamp) {
  // 9 x 9 samples, B = T = 4: L = 1, canvas 8 texels, texel c centred on grid x = c + 0.5.
  TextureLayout lay{1, 4, 4, 9, 9};
  // Upsampling (4 pixels over 8 cells) and downsampling (40 pixels) of value = 4 px + 20
  // (extent placement: pixel centre px = gx * iw / 8 - 0.5), and one pixel per sample
  // (px = gx). Bilinear interpolation and area averaging keep linear functions; 8-bit
  // rounding and OpenCV's 1/32-pixel interpolation steps allow about 1.
  for (int iw : {4, 40, 9}) {
    cv::Mat img(iw, iw, CV_8UC1);
    for (int r = 0; r < iw; ++r)
      for (int c = 0; c < iw; ++c) img.at<unsigned char>(r, c) = static_cast<unsigned char>(std::lround(200.0 * c / iw + 20));
    const ImagePlacement place = place_image(iw, iw, 9, 9);
    EXPECT_EQ(place, iw == 9 ? ImagePlacement::samples : ImagePlacement::extent);
    const cv::Mat canvas = leaf_canvas(img, place, lay);
    for (int c = 0; c < 8; ++c) {
      const double gx = c + 0.5;
      const double px = place == ImagePlacement::samples ? gx : gx * iw / 8.0 - 0.5;
      const double want = 200.0 * std::clamp(px, 0.0, iw - 1.0) / iw + 20;
      EXPECT_NEAR(canvas.at<unsigned char>(3, c), want, 1.6) << "iw " << iw << " texel " << c;
    }
  }
}

TEST(TerrainTexture, AGeoreferencedImageMapsWorldPositionsToItsPixels) {
  // DEM: 9 rows, samples at x = 100 + 10 i, y = 200 + 10 j. Image: 5 m pixels, south-west
  // pixel centred on (90, 190), 40 rows.
  const ImageFrame f = georeferenced_frame({100, 200, 10, 10, 9}, {90, 190, 5, 5, 40});
  for (double gx : {0.0, 3.5, 8.0})
    for (double gy : {0.0, 2.25, 8.0}) {
      const double x = 100 + 10 * gx, y = 200 + 10 * gy;
      const double px = (x - 90) / 5, py = 39 - (y - 190) / 5;  // rows from the north
      EXPECT_NEAR(gx * f.sx + f.ox, px, 1e-12);
      EXPECT_NEAR((9 - 1 - gy) * f.sy + f.oy, py, 1e-12);
    }
}

TEST(TerrainTexture, AnImageOfTheWrongShapeIsBadInput) {
  EXPECT_EQ(place_image(129, 129, 129, 129), ImagePlacement::samples);
  EXPECT_EQ(place_image(256, 128, 129, 65), ImagePlacement::extent);
  EXPECT_EQ(place_image(257, 128, 129, 65), ImagePlacement::extent);  // within a pixel
  try {
    place_image(100, 20, 129, 129);
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("100 x 20"), std::string::npos);
  }
}

TEST(TerrainTexture, PixelsBecomeEightBitGreyOrRgb) {
  cv::Mat m16(2, 2, CV_16UC4, cv::Scalar(65535, 257, 0, 1000));
  const cv::Mat t = texture_pixels(m16);
  ASSERT_EQ(t.type(), CV_8UC3);
  EXPECT_EQ(t.at<cv::Vec3b>(1, 1), cv::Vec3b(255, 1, 0));
  EXPECT_THROW(texture_pixels(cv::Mat(2, 2, CV_32FC1, cv::Scalar(0.5))), fest::Error);
}

TEST(TerrainTexture, HillshadeLightsSlopesFacingTheNorthWest) {
  // A ridge along the south-west/north-east diagonal: the north-west flank faces the
  // sun (azimuth 315 degrees), the south-east flank turns away; heights are symmetric.
  HeightGrid g;
  g.width = g.height = 21;
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 21; ++i) g.h.push_back(100 - 3.0 * std::abs(i - j));
  const cv::Mat img = hillshade_image(g, 1, 1);
  ASSERT_EQ(img.rows, 21);
  // Sample (5, 10) lies north-west of the ridge (j > i), (10, 5) south-east; rows are
  // from the north.
  const cv::Vec3b nw = img.at<cv::Vec3b>(20 - 10, 5), se = img.at<cv::Vec3b>(20 - 5, 10);
  for (int k = 0; k < 3; ++k) EXPECT_GT(nw[k], se[k]);
}

TEST(TerrainTexture, ClosingOnlyTilesUseTheTextureOfTheAncestorTheRuleChose) {
  // Flat ground with one 300 m block inside leaf tile (3, 3, 3): a camera hovering beside
  // the block draws that tile at level 3, while the flat level-1 tile east of it is far
  // enough for level 1 -- two levels apart, so closing splits it.
  const PyramidLayout L = fest::test::small_layout();
  auto z_range = [&](const TileId& t) {
    const int c = L.cells[t.level];
    const bool block = t.x * c <= 58 && (t.x + 1) * c >= 54 && t.y * c <= 58 && (t.y + 1) * c >= 54;
    return std::array<double, 2>{0, block ? 300.0 : 0.0};
  };
  Camera cam;
  cam.eye = {560, 560, 290};
  cam.target = {1000, 1000, 0};
  cam.fovy_deg = 70;
  cam.width = 320;
  cam.height = 240;
  cam.tau_px = 24;
  const Selection sel = select_tiles(L, cam, z_range);
  std::map<TileId, bool> drawn;
  for (const auto& s : sel.tiles) drawn[s.id] = s.closing_only;
  int closing = 0;
  for (const auto& s : sel.tiles) {
    if (!s.closing_only) {
      EXPECT_EQ(s.texture, s.id);
      continue;
    }
    ++closing;
    const int d = s.id.level - s.texture.level;
    EXPECT_GT(d, 0) << "an ancestor's texture";
    EXPECT_EQ(s.id.x >> d, s.texture.x);
    EXPECT_EQ(s.id.y >> d, s.texture.y);
    EXPECT_FALSE(drawn.count(s.texture)) << "the ancestor itself is not drawn";
    // The ancestor was chosen by the distance rule: it is not a closing split itself,
    // i.e. its parent was subdivided for distance (it lies at the level the rule gave).
    EXPECT_EQ(s.texture.level, 1);
  }
  EXPECT_GT(closing, 0);
}

}  // namespace
