// Form factors against closed forms (docs/radiosity.md §3, §7): parallel unit squares at
// distance 1, F = 0.19982; perpendicular unit squares sharing an edge, F = 0.20004 (the
// standard tabulated values, e.g. Howell's catalogue C-11 and C-14); a differential area
// under a square (Howell B-3, summed over four corner rectangles).

#include <cmath>

#include <gtest/gtest.h>

#include "radiosity/form_factors.hpp"
#include "radiosity/hemicube.hpp"
#include "radiosity/polygon_ff.hpp"
#include "radiosity/scene.hpp"
#include "radiosity_scenes.hpp"

namespace fest::radiosity {
namespace {

using V = Eigen::Vector3d;
using test::square;

// Facing down at z = 1 (normal -z) and up at z = 0 (normal +z).
Polygon top() { return square(V(0, 0, 1), V(0, 1, 1), V(1, 1, 1), V(1, 0, 1)); }
Polygon bottom() { return square(V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)); }
// The wall x = 0 facing +x, sharing the edge y = 0..1 at z = 0 with bottom().
Polygon wall() { return square(V(0, 0, 0), V(0, 1, 0), V(0, 1, 1), V(0, 0, 1)); }

double corner_rectangle(double a, double b, double h) {  // Howell B-3, parallel, corner above
  const double x = a / h, y = b / h;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
         (2 * M_PI);
}

TEST(RadiosityFormFactors, PolygonOrientationAndNormals) {
  EXPECT_NEAR(bottom().normal().z(), 1, 1e-15);
  EXPECT_NEAR(top().normal().z(), -1, 1e-15);
  EXPECT_NEAR(wall().normal().x(), 1, 1e-15);
}

TEST(RadiosityFormFactors, PointToSquareMatchesClosedForm) {
  // Point at (0.3, 0.4, 0) under the top square: four corner rectangles.
  const double x = 0.3, y = 0.4, h = 1;
  const double expected = corner_rectangle(x, y, h) + corner_rectangle(1 - x, y, h) + corner_rectangle(x, 1 - y, h) +
                          corner_rectangle(1 - x, 1 - y, h);
  EXPECT_NEAR(point_polygon_ff(V(x, y, 0), V(0, 0, 1), top()), expected, 1e-12);
  // Behind the point: nothing.
  EXPECT_EQ(point_polygon_ff(V(x, y, 0), V(0, 0, -1), top()), 0.0);
}

TEST(RadiosityFormFactors, AnalyticParallelAndPerpendicularSquares) {
  EXPECT_NEAR(polygon_polygon_ff(bottom(), top()), 0.19982, 0.19982 * 5e-4);
  EXPECT_NEAR(polygon_polygon_ff(bottom(), wall()), 0.20004, 0.20004 * 5e-3);
  // Reciprocity between unequal polygons: A_i F_ij = A_j F_ji.
  const Polygon small = square(V(0.2, 0.2, 0), V(0.5, 0.2, 0), V(0.5, 0.7, 0), V(0.2, 0.7, 0));
  const Polygon tilted = square(V(0, 0, 1), V(0, 1, 1.3), V(1, 1, 1.3), V(1, 0, 1));
  const double fij = polygon_polygon_ff(small, tilted), fji = polygon_polygon_ff(tilted, small);
  EXPECT_NEAR(small.area() * fij, tilted.area() * fji, 0.02 * small.area() * fij);
}

TEST(RadiosityFormFactors, HemicubeDeltaTableSumsToOne) {
  Hemicube cube(256);
  EXPECT_NEAR(cube.raw_sum(), 1.0, 1e-3);
}

TEST(RadiosityFormFactors, HemicubeMatchesTheSquares) {
  FormFactorOptions o;
  o.engine = Engine::hemicube;
  o.hemicube_res = 256;
  EXPECT_NEAR(polygon_form_factor(bottom(), top(), o, 16), 0.19982, 0.19982 * 0.01);
  EXPECT_NEAR(polygon_form_factor(bottom(), wall(), o, 16), 0.20004, 0.20004 * 0.01);
}

TEST(RadiosityFormFactors, RaycastMatchesTheSquares) {
  FormFactorOptions o;
  o.engine = Engine::raycast;
  o.samples = 64;
  EXPECT_NEAR(polygon_form_factor(bottom(), top(), o, 16), 0.19982, 0.19982 * 0.02);
  // Wallace's disc approximation underestimates where the receiver nears the shared
  // edge (r^2 comparable to A/S): the error is the method's, checked loosely.
  EXPECT_NEAR(polygon_form_factor(bottom(), wall(), o, 16), 0.20004, 0.20004 * 0.15);
}

TEST(RadiosityFormFactors, HybridMatchesTheClosedFormUnderALamp) {
  // A 100 x 100 lamp 300 above a floor of 10 x 10 elements: the hybrid engine's F_{e->lamp}
  // is the exact point value at each element centre (Howell B-3), no pixel aliasing.
  Model m;
  m.diagonal = 600;
  auto add_patch = [&](const Polygon& poly, int split) {
    Patch p;
    p.poly = poly;
    p.area = poly.area();
    p.centroid = poly.centroid();
    p.normal = poly.normal();
    p.object = 0;
    m.patches.push_back(p);
    for (const Polygon& q : split_polygon(poly, poly.longest_edge() / split)) {
      Element e;
      e.poly = q;
      e.area = q.area();
      e.centroid = q.centroid();
      e.normal = q.normal();
      e.patch = static_cast<int>(m.patches.size()) - 1;
      m.patches.back().elements.push_back(static_cast<int>(m.elements.size()));
      m.elements.push_back(e);
    }
  };
  add_patch(square(V(0, 0, 0), V(400, 0, 0), V(400, 400, 0), V(0, 400, 0)), 40);     // floor, +z
  add_patch(square(V(150, 150, 300), V(150, 250, 300), V(250, 250, 300), V(250, 150, 300)), 1);  // lamp, -z
  m.occluders = {m.patches[0].poly, m.patches[1].poly};
  m.objects.resize(1);
  FormFactorOptions o;
  o.engine = Engine::hybrid;
  o.hemicube_res = 256;
  FormFactors ff(m, o);
  std::vector<double> recv, row;
  ff.shoot(1, recv, row);
  double worst = 0;
  // Against the contour integral at the element centres (tied to Howell B-3 by
  // PointToSquareMatchesClosedForm).
  for (int e : m.patches[0].elements) {
    const V c = m.elements[e].centroid;
    const double exact = point_polygon_ff(c, V(0, 0, 1), m.patches[1].poly);
    worst = std::max(worst, std::abs(recv[e] - exact) / exact);
  }
  EXPECT_LT(worst, 1e-6);
  // The plain hemicube's pixel counts alias on 10-unit elements (about 18 pixels each).
  FormFactorOptions h = o;
  h.engine = Engine::hemicube;
  FormFactors fh(m, h);
  fh.shoot(1, recv, row);
  double worst_h = 0;
  for (int e : m.patches[0].elements) {
    const V c = m.elements[e].centroid;
    worst_h = std::max(worst_h, std::abs(recv[e] - point_polygon_ff(c, V(0, 0, 1), m.patches[1].poly)) /
                                    point_polygon_ff(c, V(0, 0, 1), m.patches[1].poly));
  }
  EXPECT_GT(worst_h, 0.02);
}

TEST(RadiosityFormFactors, HemicubeSeesTheWholeClosedCube) {
  // From the centre of the floor every pixel shows a wall: the five other faces take
  // 0.19982 (opposite) and 4 x 0.20004 in the limit of small hemicube pixels, by
  // closure; F_{dA->top} from the centre point is 4 x corner_rectangle(0.5, 0.5, 1).
  Hemicube cube(256);
  std::vector<Polygon> faces = {top(), wall(), square(V(1, 0, 0), V(1, 0, 1), V(1, 1, 1), V(1, 1, 0)),
                                square(V(0, 0, 0), V(0, 0, 1), V(1, 0, 1), V(1, 0, 0)),
                                square(V(0, 1, 0), V(1, 1, 0), V(1, 1, 1), V(0, 1, 1))};
  std::vector<const Polygon*> items;
  for (const auto& f : faces) items.push_back(&f);
  std::vector<std::uint8_t> draw(items.size(), 1);
  std::vector<double> ff;
  cube.project(V(0.5, 0.5, 0), V(0, 0, 1), items, draw, 1e-9, 2, ff);
  double sum = 0;
  for (double f : ff) sum += f;
  EXPECT_NEAR(sum, 1.0, 1e-9);
  EXPECT_NEAR(ff[0], 4 * corner_rectangle(0.5, 0.5, 1), 2e-3);
  // Symmetry of the four walls.
  // (Pixel centres on the diagonals of the top face are ties, settled by item order.)
  for (int k = 2; k < 5; ++k) EXPECT_NEAR(ff[k], ff[1], 1e-3);
  // The same for any thread count, bit for bit.
  std::vector<double> ff1;
  cube.project(V(0.5, 0.5, 0), V(0, 0, 1), items, draw, 1e-9, 1, ff1);
  EXPECT_EQ(ff, ff1);
}

}  // namespace
}  // namespace fest::radiosity
