// Globally linear fields are reproduced exactly by the piecewise-linear interpolant, so
// the locally exact method must follow the analytic solution x(t) = exp(tA) x0 +
// t phi1(tA) b to round-off on any grid (docs/lemtrace.md §2, §5). The expected
// values come from the mathematics: the exponential of the known A (Eigen's Pade
// scaling-and-squaring) and, for the rotations, cos/sin directly.

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"

namespace {

using namespace fest::lemtrace;

Vec3 analytic(const LinearField& f, const Vec3& x0, double t) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  M.topLeftCorner<3, 3>() = f.A * t;
  M.topRightCorner<3, 1>() = f.b * t;
  const Eigen::Matrix4d E = M.exp();
  return E.topLeftCorner<3, 3>() * x0 + E.topRightCorner<3, 1>();
}

FieldGrid make_grid(const std::string& kind, int n, double jitter, bool hex, Precompute mode = Precompute::lazy) {
  GenOptions o;
  o.kind = kind;
  o.n = n;
  o.jitter = jitter;
  o.seed = 7;
  o.hex = hex;
  GeneratedGrid g = generate(o);
  MeshReport report;
  TetMesh mesh = build_tet_mesh(g.points, g.vectors, g.cells, BuildOptions{}, &report);
  return FieldGrid(std::move(mesh), ClassifyParams{}, mode, 2);
}

// Largest distance between the traced vertices and the analytic path at their times.
double max_error(const FieldGrid& grid, const LinearField& f, const Vec3& seed, const TraceOptions& o,
                 Polyline* out = nullptr) {
  Polyline line = trace(grid, seed, 0.0, o);
  EXPECT_GE(line.x.size(), 2u);
  double err = 0;
  for (std::size_t i = 0; i < line.x.size(); ++i)
    err = std::max(err, (line.x[i] - analytic(f, seed, line.t[i])).norm());
  if (out) *out = line;
  return err;
}

struct Case {
  const char* kind;
  Vec3 seed;
};

class LinearFields : public ::testing::TestWithParam<Case> {};

TEST_P(LinearFields, LemMatchesClosedFormOnJitteredGrid) {
  const Case c = GetParam();
  bool linear = false;
  const LinearField f = linear_kind(c.kind, &linear);
  ASSERT_TRUE(linear);
  const FieldGrid grid = make_grid(c.kind, 6, 0.2, false);
  TraceOptions o;
  o.max_time = 12;
  Polyline line;
  const double err = max_error(grid, f, c.seed, o, &line);
  EXPECT_LE(err, 1e-10) << c.kind << ": " << line.x.size() << " vertices, reason " << reason_name(line.reason);
  EXPECT_NE(line.reason, Reason::none);
  for (std::size_t i = 1; i < line.t.size(); ++i) EXPECT_GE(line.t[i], line.t[i - 1]);
}

INSTANTIATE_TEST_SUITE_P(Kinds, LinearFields,
                         ::testing::Values(Case{"helix", Vec3(0.5, 0.1, -0.9)}, Case{"rotation", Vec3(0.55, 0.1, 0.13)},
                                           Case{"saddle", Vec3(0.05, 0.7, 0.2)}, Case{"node", Vec3(0.8, 0.7, -0.6)},
                                           Case{"spiral", Vec3(0.7, 0.2, -0.5)}, Case{"shear", Vec3(-0.9, 0.3, 0.1)},
                                           Case{"uniform", Vec3(-0.9, -0.8, -0.7)},
                                           Case{"jordan", Vec3(0.6, 0.5, 0.3)}),
                         [](const auto& param_info) { return std::string(param_info.param.kind); });

TEST(LemtraceAnalytic, HelixIsACircleWithConstantRise) {
  // x' = -y, y' = x, z' = 0.05: radius constant, angle = t, z = z0 + 0.05 t.
  const FieldGrid grid = make_grid("helix", 8, 0.2, false);
  const Vec3 seed(0.6, 0.0, -0.9);
  TraceOptions o;
  Polyline line = trace(grid, seed, 0.0, o);
  ASSERT_GT(line.x.size(), 20u);
  EXPECT_EQ(line.reason, Reason::out_of_domain);
  for (std::size_t i = 0; i < line.x.size(); ++i) {
    const double t = line.t[i];
    const Vec3 expected(0.6 * std::cos(t), 0.6 * std::sin(t), -0.9 + 0.05 * t);
    EXPECT_LE((line.x[i] - expected).norm(), 1e-10) << "vertex " << i << " t=" << t;
  }
  // It leaves through the top face z = 1 after (1.9 / 0.05) = 38 time units.
  EXPECT_NEAR(line.t.back(), 38.0, 1e-9);
}

TEST(LemtraceAnalytic, CircleTestTenRevolutions) {
  // Chapter Fig. 9.3/9.4: a particle in circular flow around a sphere stays on its circle.
  const FieldGrid grid = make_grid("sphere-rotation", 12, 0.2, false);
  const Vec3 seed(0.7, 0.0, 0.05);
  TraceOptions o;
  o.max_time = 20 * M_PI;
  Polyline line = trace(grid, seed, 0.0, o);
  EXPECT_EQ(line.reason, Reason::out_of_time);
  double drift = 0;
  for (const Vec3& x : line.x) drift = std::max({drift, std::abs(std::hypot(x[0], x[1]) - 0.7), std::abs(x[2] - 0.05)});
  EXPECT_LE(drift, 1e-10);
  EXPECT_NEAR(line.t.back(), 20 * M_PI, 1e-12);
  // Heun at 0.2 cell lengths drifts visibly; RK4 less; the LEM not at all (docs/lemtrace.md §5).
  TraceOptions rk = o;
  rk.method = Method::heun;
  double heun = 0, rk4 = 0;
  for (const Vec3& x : trace(grid, seed, 0.0, rk).x) heun = std::max(heun, std::abs(std::hypot(x[0], x[1]) - 0.7));
  rk.method = Method::rk4;
  for (const Vec3& x : trace(grid, seed, 0.0, rk).x) rk4 = std::max(rk4, std::abs(std::hypot(x[0], x[1]) - 0.7));
  EXPECT_LT(drift, rk4);
  EXPECT_LT(rk4, heun);
  EXPECT_GE(heun, 1e-5);
}

TEST(LemtraceAnalytic, HexahedralGridTracesExactlyAfterSplitting) {
  bool linear = false;
  const LinearField f = linear_kind("spiral", &linear);
  const FieldGrid grid = make_grid("spiral", 5, 0.2, true);
  TraceOptions o;
  o.max_time = 10;
  EXPECT_LE(max_error(grid, f, Vec3(0.6, -0.3, 0.4), o), 1e-10);
}

TEST(LemtraceAnalytic, PrecomputeModesGiveIdenticalPaths) {
  const FieldGrid lazy = make_grid("spiral", 5, 0.2, false, Precompute::lazy);
  const FieldGrid all = make_grid("spiral", 5, 0.2, false, Precompute::all);
  const FieldGrid none = make_grid("spiral", 5, 0.2, false, Precompute::none);
  TraceOptions o;
  const Vec3 seed(0.6, -0.3, 0.4);
  const Polyline a = trace(lazy, seed, 0, o), b = trace(all, seed, 0, o), c = trace(none, seed, 0, o);
  ASSERT_EQ(a.x.size(), b.x.size());
  ASSERT_EQ(a.x.size(), c.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    EXPECT_EQ(a.x[i], b.x[i]);
    EXPECT_EQ(a.x[i], c.x[i]);
  }
}

// The tracer's straight path for the common crossing (predicted exit, speed bound from
// the record, length only when limited) against the general path alone (--root bracket
// without the prediction): the same cells, the same termination, points that agree to
// round-off of the exit search, and both on the analytic path. The node field's sink
// makes the terminal-speed test stop the line; the length limit and both directions go
// through the same code.
TEST(LemtraceAnalytic, FastCrossingMatchesTheGeneralPath) {
  const Case cases[] = {{"helix", Vec3(0.5, 0.1, -0.9)}, {"rotation", Vec3(0.55, 0.1, 0.13)},
                        {"spiral", Vec3(0.7, 0.2, -0.5)}, {"saddle", Vec3(0.05, 0.7, 0.2)},
                        {"node", Vec3(0.8, 0.7, -0.6)}};
  for (const Case& c : cases) {
    bool linear = false;
    const LinearField f = linear_kind(c.kind, &linear);
    const FieldGrid grid = make_grid(c.kind, 6, 0.2, false, Precompute::all);
    for (int variant = 0; variant < 3; ++variant) {
      TraceOptions fast;
      fast.max_time = 12;
      if (variant == 1) fast.max_length = 1.0;
      if (variant == 2) fast.direction = Direction::both;
      if (std::string(c.kind) == "node") fast.terminal_speed = 0.02;
      TraceOptions general = fast;
      general.exit.predict = false;
      const Polyline a = trace(grid, c.seed, 0, fast), b = trace(grid, c.seed, 0, general);
      EXPECT_EQ(a.reason, b.reason) << c.kind << " " << variant;
      if (std::string(c.kind) == "node" && variant == 0) {
        EXPECT_TRUE(a.reason == Reason::stagnation || a.reason == Reason::critical_point) << reason_name(a.reason);
      }
      if (variant == 1 && std::string(c.kind) != "node") {
        EXPECT_EQ(a.reason, Reason::out_of_length) << c.kind;
      }
      EXPECT_EQ(a.cells, b.cells) << c.kind << " " << variant;
      ASSERT_EQ(a.x.size(), b.x.size()) << c.kind << " " << variant;
      for (std::size_t i = 0; i < a.x.size(); ++i) {
        EXPECT_EQ(a.cell[i], b.cell[i]) << c.kind << " " << i;
        EXPECT_LE((a.x[i] - b.x[i]).norm(), 1e-11) << c.kind << " " << i;
        EXPECT_LE((a.x[i] - analytic(f, c.seed, a.t[i])).norm(), 1e-10) << c.kind << " " << i;
      }
    }
  }
}

TEST(LemtraceAnalytic, PaperNewtonAgreesWithBracket) {
  bool linear = false;
  const LinearField f = linear_kind("saddle", &linear);
  const FieldGrid grid = make_grid("saddle", 6, 0.2, false);
  TraceOptions o;
  o.exit.paper_newton = true;
  EXPECT_LE(max_error(grid, f, Vec3(0.05, 0.7, 0.2), o), 1e-10);
}

TEST(LemtraceAnalytic, BackwardReturnsToSeed) {
  // Time reversibility (docs/lemtrace.md §2).
  const FieldGrid grid = make_grid("spiral", 6, 0.2, false);
  TraceOptions o;
  o.max_steps = 40;
  const Vec3 seed(0.6, -0.3, 0.4);
  const Polyline fwd = trace(grid, seed, 0, o);
  ASSERT_EQ(fwd.reason, Reason::out_of_steps);
  TraceOptions back = o;
  back.direction = Direction::backward;
  back.max_time = fwd.t.back();
  const Polyline bwd = trace(grid, fwd.x.back(), fwd.t.back(), back);
  EXPECT_LE((bwd.x.back() - seed).norm(), 1e-9 * (2.0 / 6));
}

TEST(LemtraceAnalytic, SeedOutsideIsNotInitialized) {
  const FieldGrid grid = make_grid("helix", 4, 0.0, false);
  const Polyline line = trace(grid, Vec3(2, 0, 0), 0, TraceOptions{});
  EXPECT_EQ(line.reason, Reason::not_initialized);
  EXPECT_TRUE(line.x.empty());
}

TEST(LemtraceAnalytic, RungeKuttaConvergesToTheSamePath) {
  // docs/lemtrace.md §5: RK45 at a tight tolerance on the same piecewise-linear field agrees.
  bool linear = false;
  const LinearField f = linear_kind("helix", &linear);
  const FieldGrid grid = make_grid("helix", 6, 0.2, false);
  TraceOptions o;
  o.method = Method::rk45;
  o.tolerance = 1e-12;
  o.max_time = 5;
  const Vec3 seed(0.5, 0.1, -0.9);
  const Polyline line = trace(grid, seed, 0, o);
  EXPECT_LE((line.x.back() - analytic(f, seed, line.t.back())).norm(), 1e-8);
}

}  // namespace

namespace {

// Stokes stream function of potential flow past a sphere (R = 0.4, U = e_z), constant
// on every streamline: psi = 1/2 rho^2 (1 - R^3 / r^3).
double stream_function(const Vec3& x) {
  const double r = x.norm(), R3 = 0.4 * 0.4 * 0.4;
  return 0.5 * (x[0] * x[0] + x[1] * x[1]) * (1.0 - R3 / (r * r * r));
}

TEST(LemtraceAnalytic, NonlinearFieldConvergesAtTheInterpolationOrder) {
  // docs/lemtrace.md §5: the LEM is exact for the piecewise-linear field, so its drift in psi is
  // the interpolation error, O(h^2): from n = 8 to n = 32 (two halvings of h) it must
  // shrink by at least 3.5^2.
  double drift[2] = {0, 0};
  int which = 0;
  for (int n : {8, 32}) {
    const FieldGrid grid = make_grid("sphere-potential", n, 0.2, false);
    for (double rho : {0.5, 0.6, 0.7})
      for (double phi : {0.3, 1.3, 2.9, 4.0}) {
        const Vec3 seed(rho * std::cos(phi), rho * std::sin(phi), -0.9);
        const Polyline line = trace(grid, seed, 0.0, TraceOptions{});
        EXPECT_EQ(line.reason, Reason::out_of_domain);
        for (const Vec3& x : line.x)
          drift[which] = std::max(drift[which], std::abs(stream_function(x) - stream_function(seed)));
      }
    ++which;
  }
  EXPECT_GT(drift[0], 0);
  EXPECT_GE(drift[0] / drift[1], 3.5 * 3.5) << drift[0] << " -> " << drift[1];
}

TEST(LemtraceAnalytic, SamplesInsideCellsAreOnThePath) {
  bool linear = false;
  const LinearField f = linear_kind("spiral", &linear);
  const FieldGrid grid = make_grid("spiral", 5, 0.2, false);
  TraceOptions o;
  o.samples_per_cell = 4;
  o.max_time = 8;
  Polyline line;
  EXPECT_LE(max_error(grid, f, Vec3(0.6, -0.3, 0.4), o, &line), 1e-10);
  // Three interior points and the exit per cell; the last cell ends at --max-time.
  EXPECT_GE(line.x.size(), 4 * static_cast<std::size_t>(line.cells - 1));
}

}  // namespace
