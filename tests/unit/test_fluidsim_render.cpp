// lib/fluidsim/render: colour maps and the range checks of render_plane, in the domain's
// terms (the tool names its flags).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "fluidsim/render.hpp"

namespace fest::fluidsim {
namespace {

TEST(FluidsimRender, ColourMapsEndsAndClamping) {
  EXPECT_EQ(colour(Colormap::gray, 0.25), (std::array<double, 3>{0.25, 0.25, 0.25}));
  EXPECT_EQ(colour(Colormap::gray, 2.0), (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_EQ(colour(Colormap::gray, NAN), (std::array<double, 3>{0.0, 0.0, 0.0}));
  // The diverging map is white at its centre.
  const auto mid = colour(Colormap::velocity, 0.5);
  for (double c : mid) EXPECT_DOUBLE_EQ(c, 1.0);
  // Inferno runs from near black to a light yellow.
  const auto lo = colour(Colormap::inferno, 0.0), hi = colour(Colormap::inferno, 1.0);
  EXPECT_LT(lo[0] + lo[1] + lo[2], 0.1);
  EXPECT_GT(hi[0] + hi[1], 1.5);
}

TEST(FluidsimRender, OutOfRangeAxisAndSliceNameNoFlag) {
  const std::vector<double> field(4 * 4 * 4, 1.0);
  RenderOptions o;
  o.mode = RenderMode::slice;
  auto message = [&] {
    try {
      render_plane(field, {4, 4, 4}, 3, o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  o.axis = 3;
  EXPECT_EQ(message(), "viewing axis 3 is not 0, 1 or 2");
  o.axis = 2;
  o.index = 4;
  EXPECT_EQ(message(), "slice index 4 is out of range [0, 3]");
  o.index = 3;
  const Plane p = render_plane(field, {4, 4, 4}, 3, o);
  EXPECT_EQ(p.width, 4);
  EXPECT_EQ(p.height, 4);
  for (double v : p.values) EXPECT_EQ(v, 1.0);
}

}  // namespace
}  // namespace fest::fluidsim
