// quatpath's mathematics against closed forms (docs/quatpath.md): unit norm, constant
// angular speed of slerp, C1 squad at the keys, the per-segment reversal on a 350-degree
// turn, constant speed after arc-length reparametrisation, and bad keys.

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "motionpath/path.hpp"

using namespace fest::motionpath;

namespace {

const double pi = std::acos(-1.0);

// Rotation angle between two unit quaternions, in [0, 2 pi): 2 acos |a.b| is the
// smallest; this one keeps the sign convention of the 4-D arc (2 x the 4-D angle).
double arc4(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::clamp(dot(a, b), -1.0, 1.0)); }

// Angular velocity vector (world frame) of q(t) by central differences: 2 dq/dt q*.
Vec3 omega(const Path& p, double t, double h) {
  const Quat a = p.at(t - h).q, b = p.at(t + h).q;
  const Quat dq{(b.w - a.w) / (2 * h), (b.x - a.x) / (2 * h), (b.y - a.y) / (2 * h), (b.z - a.z) / (2 * h)};
  const Quat w = dq * conj(p.at(t).q);
  return {2 * w.x, 2 * w.y, 2 * w.z};
}

Key key(double t, Vec3 p, Quat q) {
  Key k;
  k.t = t;
  k.p = p;
  k.q = q;
  return k;
}

std::vector<Key> random_keys(int n, std::uint64_t seed) {
  fest::Rng rng(seed);
  std::vector<Key> keys;
  for (int i = 0; i < n; ++i) {
    Quat q{rng.normal(), rng.normal(), rng.normal(), rng.normal()};
    keys.push_back(key(i, {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)}, normalized(q)));
  }
  return keys;
}

}  // namespace

TEST(MotionpathQuat, StaysUnitTo1e12) {
  for (auto mode : {OrientationMode::slerp, OrientationMode::squad}) {
    PathOptions o;
    o.orientation = mode;
    Path p(random_keys(12, 5), o);
    double worst = 0;
    for (const Pose& s : p.sample(97.0, true)) worst = std::max(worst, std::fabs(norm(s.q) - 1.0));
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(MotionpathQuat, SlerpHasConstantAngularSpeed) {
  // From identity to 120 degrees about (1,2,2)/3 in 1 s: |omega| = 2 pi / 3 everywhere,
  // and the angle from the start grows linearly.
  const Vec3 axis{1.0 / 3, 2.0 / 3, 2.0 / 3};
  const Quat q1 = from_axis_angle(axis, 2 * pi / 3);
  Path p({key(0, {0, 0, 0}, Quat{}), key(1, {1, 0, 0}, q1)}, PathOptions{});
  for (double t = 0.05; t < 1.0; t += 0.05) {
    EXPECT_NEAR(norm(omega(p, t, 1e-6)), 2 * pi / 3, 1e-6) << t;
    EXPECT_NEAR(arc4(Quat{}, p.at(t).q), t * 2 * pi / 3, 1e-9) << t;
  }
}

TEST(MotionpathQuat, SquadIsC1AtTheKeys) {
  PathOptions o;
  o.orientation = OrientationMode::squad;
  Path p(random_keys(6, 11), o);
  for (int i = 1; i < 5; ++i) {
    const double h = 1e-5;
    // One-sided derivatives at key i, from the left segment and from the right one.
    auto deriv = [&](double t0, double t1) {
      const Quat a = p.at(t0).q, b = p.at(t1).q;
      return Quat{(b.w - a.w) / (t1 - t0), (b.x - a.x) / (t1 - t0), (b.y - a.y) / (t1 - t0), (b.z - a.z) / (t1 - t0)};
    };
    const Quat left = deriv(i - 2 * h, i - h), right = deriv(i + h, i + 2 * h);
    const Quat left2 = deriv(i - h, i), right2 = deriv(i, i + h);
    // Richardson: extrapolate both one-sided differences to the key.
    auto ex = [](const Quat& near, const Quat& far) {
      return Quat{2 * near.w - far.w, 2 * near.x - far.x, 2 * near.y - far.y, 2 * near.z - far.z};
    };
    const Quat dl = ex(left2, left), dr = ex(right2, right);
    const double diff = norm(Quat{dl.w - dr.w, dl.x - dr.x, dl.y - dr.y, dl.z - dr.z});
    EXPECT_LT(diff, 1e-4 * std::max(1.0, norm(dl))) << "key " << i;
  }
  // slerp, by contrast, has a corner there.
  Path s(random_keys(6, 11), PathOptions{});
  const Vec3 a = omega(s, 2 - 1e-3, 1e-5), b = omega(s, 2 + 1e-3, 1e-5);
  EXPECT_GT(norm(a - b), 1e-2);
}

TEST(MotionpathQuat, ReversalRuleOnA350DegreeTurn) {
  // Key 1 is 350 degrees about z from key 0. The short way turns -10 degrees; the
  // requested long way turns +350 degrees (seed §18: per-segment reversal).
  const Quat q1 = from_axis_angle({0, 0, 1}, 350.0 * pi / 180);
  std::vector<Key> keys{key(0, {0, 0, 0}, Quat{}), key(1, {0, 0, 0}, q1)};
  Path shortest(keys, PathOptions{});
  keys[0].way = Way::longest;
  Path longest(keys, PathOptions{});
  auto yaw_deg = [](const Quat& q) {
    const Vec3 x = rotate(q, {1, 0, 0});
    return std::atan2(x.y, x.x) * 180 / pi;
  };
  EXPECT_NEAR(yaw_deg(shortest.at(0.5).q), -5.0, 1e-9);
  EXPECT_NEAR(yaw_deg(longest.at(0.5).q), 175.0, 1e-9);
  EXPECT_NEAR(yaw_deg(longest.at(0.25).q), 87.5, 1e-9);
  EXPECT_NEAR(norm(omega(shortest, 0.5, 1e-6)), 10.0 * pi / 180, 1e-6);
  EXPECT_NEAR(norm(omega(longest, 0.5, 1e-6)), 350.0 * pi / 180, 1e-6);
  // Either way ends on the key's rotation (q or -q).
  EXPECT_NEAR(std::fabs(dot(shortest.at(1).q, q1)), 1.0, 1e-12);
  EXPECT_NEAR(std::fabs(dot(longest.at(1).q, q1)), 1.0, 1e-12);
}

TEST(MotionpathPosition, CatmullRomInterpolatesAndLinearIsLinear) {
  auto keys = random_keys(5, 3);
  Path cr(keys, PathOptions{});
  for (const Key& k : keys) {
    const Vec3 p = cr.at(k.t).p;
    EXPECT_NEAR(norm(p - k.p), 0.0, 1e-12);
  }
  // Uniform Catmull-Rom tangent at an inner key: (p_{i+1} - p_{i-1}) / 2 per unit time.
  const Vec3 v = (1.0 / 2e-6) * (cr.at(2 + 1e-6).p - cr.at(2 - 1e-6).p);
  const Vec3 want = 0.5 * (keys[3].p - keys[1].p);
  EXPECT_NEAR(norm(v - want), 0.0, 1e-5);
  PathOptions lo;
  lo.position = PositionMode::linear;
  Path lin(keys, lo);
  const Vec3 mid = lin.at(1.25).p, w = 0.75 * keys[1].p + 0.25 * keys[2].p;
  EXPECT_NEAR(norm(mid - w), 0.0, 1e-12);
}

TEST(MotionpathPosition, KochanekBartelsTensionOneStopsAtKeys) {
  auto keys = random_keys(4, 9);
  for (auto& k : keys) k.tension = 1.0;  // zero tangents: velocity vanishes at every key
  PathOptions o;
  o.position = PositionMode::kb;
  Path p(keys, o);
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_NEAR(norm(p.velocity_param(s, 0.0)), 0.0, 1e-12);
    EXPECT_NEAR(norm(p.velocity_param(s, 1.0)), 0.0, 1e-12);
  }
}

TEST(MotionpathArcLength, ConstantSpeedWithin0_1Percent) {
  PathOptions o;
  o.constant_speed = true;
  Path p(random_keys(7, 21), o);
  // Speed |dp/dt| by central differences at every frame time against length / duration.
  const double want = p.length() / (p.t_end() - p.t_begin());
  double worst = 0;
  for (const Pose& f : p.sample(200.0, false)) {
    const double t = std::clamp(f.t, p.t_begin() + 1e-6, p.t_end() - 1e-6);
    const double speed = norm(p.at(t + 1e-6).p - p.at(t - 1e-6).p) / 2e-6;
    worst = std::max(worst, std::fabs(speed / want - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  // Without reparametrisation the same path's speed varies a lot.
  Path q(random_keys(7, 21), PathOptions{});
  const auto f2 = q.sample(200.0, false);
  double lo = 1e300, hi = 0;
  for (std::size_t i = 1; i < f2.size(); ++i) {
    const double d = norm(f2[i].p - f2[i - 1].p);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_GT(hi / lo, 1.5);
}

TEST(MotionpathArcLength, StraightLineLengthIsExact) {
  PathOptions o;
  o.position = PositionMode::linear;
  Path p({key(0, {0, 0, 0}, Quat{}), key(2, {3, 4, 0}, Quat{}), key(3, {3, 4, 12}, Quat{})}, o);
  EXPECT_NEAR(p.length(), 17.0, 1e-12);
}

TEST(MotionpathResample, ThirtyToTenFps) {
  std::vector<Key> keys;
  for (int k = 0; k <= 30; ++k) keys.push_back(key(k / 30.0, {static_cast<double>(k), 0, 0}, Quat{}));
  PathOptions o;
  o.position = PositionMode::linear;
  Path p(keys, o);
  const auto f = p.sample(10.0, true);
  ASSERT_EQ(f.size(), 11u);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i].p.x, 3.0 * static_cast<double>(i), 1e-9);
}

TEST(MotionpathBadKeys, NanNonMonotoneZeroQuaternionFullTurn) {
  EXPECT_THROW(Path({key(0, {0, 0, 0}, Quat{})}, PathOptions{}), fest::Error);
  EXPECT_THROW(Path({key(0, {0, NAN, 0}, Quat{}), key(1, {0, 0, 0}, Quat{})}, PathOptions{}), fest::Error);
  EXPECT_THROW(Path({key(1, {0, 0, 0}, Quat{}), key(1, {1, 0, 0}, Quat{})}, PathOptions{}), fest::Error);
  EXPECT_THROW(Path({key(0, {0, 0, 0}, Quat{0, 0, 0, 0}), key(1, {1, 0, 0}, Quat{})}, PathOptions{}), fest::Error);
  Key a = key(0, {0, 0, 0}, Quat{});
  a.way = Way::longest;
  EXPECT_THROW(Path({a, key(1, {1, 0, 0}, Quat{})}, PathOptions{}), fest::Error);  // 360 degrees about nothing
}
