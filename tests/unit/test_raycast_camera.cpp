// Camera geometry (docs/volrender.md "Cameras"): off-axis = symmetric, the mirror's
// line-of-sight property to 1e-9, stereo zero parallax and disparity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "raycast/camera.hpp"

using namespace fest::raycast;

namespace {

Vec3 unit_dir(const Vec3& d) { return normalized(d); }

// The continuous pixel (x, y) of an off-axis camera whose screen point is p.
std::pair<double, double> pixel_of(const Camera& c, const Vec3& p) {
  // p = pa + u (pb - pa) + v (pc - pa); solve by projecting on the (orthogonal) screen axes
  const Vec3 e1 = c.pb - c.pa, e2 = c.pc - c.pa, q = p - c.pa;
  const double a = dot(e1, e1), b = dot(e1, e2), d = dot(e2, e2), r1 = dot(q, e1), r2 = dot(q, e2);
  const double det = a * d - b * b;
  const double u = (d * r1 - b * r2) / det, v = (a * r2 - b * r1) / det;
  return {u * c.width, c.height - v * c.height};
}

}  // namespace

TEST(RaycastCamera, OffAxisOnAxisEqualsSymmetricPerspective) {
  const double Ws = 0.8, Hs = 0.6, D = 1.7;
  const Camera off = off_axis_camera({-Ws / 2, -Hs / 2, 0}, {Ws / 2, -Hs / 2, 0}, {-Ws / 2, Hs / 2, 0}, {0, 0, D}, 64, 48);
  const Camera sym = look_at_camera({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 2 * std::atan(Hs / (2 * D)) * 180 / M_PI, 64, 48);
  for (int j = 0; j < 48; j += 7)
    for (int i = 0; i < 64; i += 5) {
      const Vec3 a = unit_dir(off.ray(i + 0.5, j + 0.5).dir), b = unit_dir(sym.ray(i + 0.5, j + 0.5).dir);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12);
    }
}

TEST(RaycastCamera, ReflectionIsAnInvolutionFixingItsPlane) {
  Mirror m;
  m.n = normalized(Vec3{0.3, 0.7071, 0.64});
  m.delta = 0.05;
  const Vec3 x{0.3, -0.2, 1.1};
  const Vec3 rr = m.reflect(m.reflect(x));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rr[k], x[k], 1e-14);
  const Vec3 on = x - (dot(m.n, x) - m.delta) * m.n;
  const Vec3 r = m.reflect(on);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[k], on[k], 1e-14);
}

// For random eyes, mirrors, screens and points P behind the mirror: the pixel p that
// shows P satisfies "R(p) lies on the line (eye, P)", i.e. the ray through p points at P.
TEST(RaycastCamera, MirrorLineOfSightTo1em9) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  int checked = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec3 pa{-0.4, -0.3, 0}, pb{0.4, -0.3, 0}, pc{-0.4, 0.3, 0};  // horizontal screen, z = 0
    Mirror m;
    m.n = normalized(Vec3{0.1 * U(rng), 0.7 + 0.1 * U(rng), 0.7 + 0.1 * U(rng)});
    m.delta = 0.05 + 0.02 * U(rng);
    const Vec3 eye{0.2 * U(rng), -0.8 + 0.1 * U(rng), 0.5 + 0.1 * U(rng)};
    Camera c = off_axis_camera(pa, pb, pc, eye, 640, 480);
    c.mirror = m;
    // a point P on the far side of the mirror from the eye
    const Vec3 P{0.3 * U(rng), 0.2 + 0.2 * U(rng), 0.3 + 0.2 * U(rng)};
    if ((dot(m.n, eye) - m.delta) * (dot(m.n, P) - m.delta) >= 0) continue;
    // R(p) on line (eye, P) and p on the screen  <=>  R(p) on the line and on R(screen plane)
    const Vec3 sn = c.screen_normal();
    const Vec3 rn = sn - 2 * dot(sn, m.n) * m.n;           // reflected plane normal
    const Vec3 rpa = m.reflect(pa);
    const Vec3 d = P - eye;
    const double t = dot(rn, rpa - eye) / dot(rn, d);
    const Vec3 p = m.reflect(eye + t * d);
    const auto [x, y] = pixel_of(c, p);
    const Ray r = c.ray(x, y);
    const Vec3 a = unit_dir(r.dir), b = unit_dir(P - eye);
    const Vec3 cr = cross(a, b);
    EXPECT_LT(norm(cr), 1e-9);
    EXPECT_GT(dot(a, b), 0);
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

// Stereo: a point on the screen plane shows at the same pixel for both eyes; a point a
// distance z behind the screen has the screen disparity ipd * z / (D + z).
TEST(RaycastCamera, StereoZeroParallaxAndDisparity) {
  const double D = 0.6, ipd = 0.064, W = 0.8;
  const Camera c = off_axis_camera({-W / 2, -0.3, 0}, {W / 2, -0.3, 0}, {-W / 2, 0.3, 0}, {0.05, 0.02, D}, 800, 600);
  const auto [L, R] = stereo_pair(c, ipd, c.screen_right());
  auto screen_hit = [&](const Camera& e, const Vec3& P) {
    const Vec3 d = P - e.eye;
    const double t = -e.eye[2] / d[2];
    return pixel_of(e, e.eye + t * d);
  };
  const Vec3 on{0.1, -0.05, 0};
  const auto l0 = screen_hit(L, on), r0 = screen_hit(R, on);
  EXPECT_EQ(l0, r0);
  const double z = 0.25;
  const Vec3 behind{0.1, -0.05, -z};
  const auto l1 = screen_hit(L, behind), r1 = screen_hit(R, behind);
  EXPECT_NEAR((r1.first - l1.first) * W / 800, ipd * z / (D + z), 1e-12);
  EXPECT_NEAR(r1.second, l1.second, 1e-9);
  // and the ray through that pixel of each eye passes through the point
  for (const auto* e : {&L, &R}) {
    const auto px = e == &L ? l1 : r1;
    const Ray r = e->ray(px.first, px.second);
    EXPECT_LT(norm(cross(normalized(r.dir), normalized(behind - e->eye))), 1e-12);
  }
}

TEST(RaycastCamera, DegenerateScreensAreRefused) {
  EXPECT_THROW(off_axis_camera({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, 8, 8), std::invalid_argument);
  EXPECT_THROW(off_axis_camera({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}, 8, 8), std::invalid_argument);
}
