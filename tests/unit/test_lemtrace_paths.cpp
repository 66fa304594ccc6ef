// Path properties on fields that are linear only cell by cell (docs/lemtrace.md §3-5):
// random vertex vectors on a jittered grid, random seeds. No NaN, a termination reason
// on every line, time monotone, every exit point on a face of the cell it leaves and
// the next cell's face; the paper's Newton agrees with the bracketing search where it
// validates, and the bracketing search never reports an exit outside the cell.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lemtrace/exit_search.hpp"
#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/locator.hpp"
#include "lemtrace/tracer.hpp"

namespace {

using namespace fest::lemtrace;

FieldGrid random_field_grid(uint64_t seed, int n) {
  GenOptions o;
  o.kind = "uniform";
  o.n = n;
  o.jitter = 0.2;
  o.seed = seed;
  GeneratedGrid g = generate(o);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> u(0.0, 1.0);
  for (Vec3& v : g.vectors) v = Vec3(u(rng), u(rng), u(rng)) + Vec3(0.8, 0.3, 0.1);
  return FieldGrid(build_tet_mesh(g.points, g.vectors, g.cells, BuildOptions{}, nullptr), ClassifyParams{},
                   Precompute::lazy, 1);
}

TEST(LemtracePaths, RandomPiecewiseLinearFields) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const FieldGrid grid = random_field_grid(seed, 6);
    std::mt19937_64 rng(seed + 100);
    std::uniform_real_distribution<double> pos(-0.95, 0.95);
    int reasons[9] = {0};
    for (int s = 0; s < 60; ++s) {
      TraceOptions o;
      o.max_time = 20;
      o.direction = s % 3 == 0 ? Direction::backward : Direction::forward;
      const Vec3 seed_point(pos(rng), pos(rng), pos(rng));
      const Polyline line = trace(grid, seed_point, 0.0, o);
      ASSERT_NE(line.reason, Reason::none);
      ASSERT_NE(line.reason, Reason::not_initialized);
      ++reasons[static_cast<int>(line.reason)];
      for (std::size_t i = 0; i < line.x.size(); ++i) {
        ASSERT_TRUE(line.x[i].allFinite());
        if (i > 0) {
          if (o.direction == Direction::forward) EXPECT_GE(line.t[i], line.t[i - 1]);
          else EXPECT_LE(line.t[i], line.t[i - 1]);
        }
      }
      // Exit points lie on the boundary of the cell they leave (some beta = 0) and
      // inside it (all beta >= 0), up to round-off.
      const bool ends_inside = line.reason == Reason::critical_point || line.reason == Reason::stagnation ||
                               line.reason == Reason::out_of_time;
      for (std::size_t i = 1; i + (ends_inside ? 1 : 0) < line.x.size(); ++i) {
        const Eigen::Vector4d b = barycentric(grid.mesh(), line.cell[i], line.x[i]);
        EXPECT_GE(b.minCoeff(), -1e-10);
        EXPECT_LE(b.minCoeff(), 1e-10) << "vertex " << i << " is not on a face of cell " << line.cell[i];
      }
    }
    EXPECT_GT(reasons[static_cast<int>(Reason::out_of_domain)], 0);
  }
}

TEST(LemtracePaths, NewtonAgreesWithBracketWhereItValidates) {
  const FieldGrid grid = random_field_grid(9, 4);
  std::mt19937_64 rng(5);
  int compared = 0;
  for (std::size_t c = 0; c < grid.mesh().tets.size(); ++c) {
    const TetGeometry g = tet_geometry(grid.mesh(), static_cast<int32_t>(c));
    // The world-frame record (the grid keeps normal cells in their barycentric frame).
    const CellRecord rec = classify(g, grid.params());
    if (rec.type != CellType::normal_real && rec.type != CellType::normal_complex) continue;
    std::uniform_real_distribution<double> w(0.05, 1.0);
    Eigen::Vector4d beta(w(rng), w(rng), w(rng), w(rng));
    beta /= beta.sum();
    const Vec3 x0 = beta[0] * g.V[0] + beta[1] * g.V[1] + beta[2] * g.V[2] + beta[3] * g.V[3];
    const CellPath path(rec, x0, 1.0);
    ExitParams bracket, newton;
    newton.paper_newton = true;
    const ExitResult a = find_exit(g, path, bracket);
    const ExitResult b = find_exit(g, path, newton);
    if (a.kind != ExitResult::exit) continue;
    EXPECT_GE(g.bary(path.position(a.tau)).minCoeff(), -1e-10);
    if (b.kind == ExitResult::exit) {
      EXPECT_NEAR(a.tau, b.tau, 1e-10 * a.tau) << "cell " << c;
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);
}

}  // namespace

namespace {

using namespace fest::lemtrace;

// The barycentric-frame record (what the grid stores for normal cells) is the same path:
// mapped back to world coordinates it agrees with the world-frame closed form, and the
// eigen-coordinate predicted exit, where it answers, gives the exit time, face and point
// of the general search in world coordinates.
TEST(LemtracePaths, BarycentricFrameRecordIsTheSamePath) {
  const FieldGrid grid = random_field_grid(11, 5);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> w(0.05, 1.0);
  int predicted = 0, normal = 0;
  for (std::size_t c = 0; c < grid.mesh().tets.size(); ++c) {
    const TetGeometry g = tet_geometry(grid.mesh(), static_cast<int32_t>(c));
    const CellRecord world = classify(g, grid.params());
    if (world.type != CellType::normal_real && world.type != CellType::normal_complex) continue;
    ++normal;
    const CellRecord local = to_barycentric_frame(g, world);
    ASSERT_TRUE(local.bary_frame);
    ASSERT_GT(local.tau_bary, 0.0f);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(local.lam[i], world.lam[i]);
    Eigen::Vector4d beta(w(rng), w(rng), w(rng), w(rng));
    beta /= beta.sum();
    const Vec3 x0 = g.point(beta);
    for (double dir : {1.0, -1.0}) {
      const CellPath pw(world, x0, dir), pl(local, Vec3(beta[1], beta[2], beta[3]), dir);
      const double tauT = g.transit_time();
      for (double f : {0.1, 0.5, 1.0}) {
        const Vec3 u = pl.position(f * tauT);
        const Vec3 xl = g.point(Eigen::Vector4d(1.0 - u.sum(), u[0], u[1], u[2]));
        EXPECT_LE((xl - pw.position(f * tauT)).norm(), 1e-12 * g.h_min) << "cell " << c;
      }
      ExitResult fast;
      if (!predicted_exit_local(local, beta, dir, fast)) continue;
      ++predicted;
      const ExitResult ref = find_exit(g, pw, ExitParams{});
      ASSERT_EQ(ref.kind, ExitResult::exit);
      EXPECT_EQ(fast.face, ref.face) << "cell " << c;
      EXPECT_NEAR(fast.tau, ref.tau, 1e-10 * ref.tau) << "cell " << c;
      EXPECT_LE((g.point(fast.beta) - ref.x).norm(), 1e-10 * g.h_min) << "cell " << c;
      EXPECT_EQ(fast.beta[fast.face], 0.0);
      EXPECT_GE(fast.beta.minCoeff(), 0.0);
      EXPECT_NEAR(fast.beta.sum(), 1.0, 1e-15);
    }
  }
  EXPECT_GT(normal, 400);
  EXPECT_GT(predicted, 100);  // random fields curve hard: the prediction declines often
}

// The tracer's common case: a normal cell entered through a face (beta_k = 0 there, the
// path moving inwards). Wherever the predicted exit answers, it is the general search's
// exit (face, time, point) in world coordinates, on cells of both normal types, on
// curved paths (the rotation grid, where faces are grazed) and on a random field.
TEST(LemtracePaths, PredictedExitFromFaceEntriesIsTheGeneralSearchs) {
  GenOptions rot;
  rot.kind = "rotation";
  rot.n = 5;
  rot.jitter = 0.25;
  rot.seed = 3;
  GeneratedGrid gr = generate(rot);
  const FieldGrid grids[2] = {random_field_grid(21, 5),
                              FieldGrid(build_tet_mesh(gr.points, gr.vectors, gr.cells, BuildOptions{}, nullptr),
                                        ClassifyParams{}, Precompute::lazy, 1)};
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> w(0.0, 1.0);
  int tried[4] = {0, 0, 0, 0}, answered[4] = {0, 0, 0, 0};
  for (const FieldGrid& grid : grids) {
    for (std::size_t c = 0; c < grid.mesh().tets.size(); ++c) {
      const TetGeometry g = tet_geometry(grid.mesh(), static_cast<int32_t>(c));
      const CellRecord world = classify(g, grid.params());
      if (world.type != CellType::normal_real && world.type != CellType::normal_complex) continue;
      const CellRecord local = to_barycentric_frame(g, world);
      const int type = static_cast<int>(world.type);
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector4d beta(0.02 + w(rng), 0.02 + w(rng), 0.02 + w(rng), 0.02 + w(rng));
        beta[k] = 0;
        beta /= beta.sum();
        const Vec3 x0 = g.point(beta);
        for (double dir : {1.0, -1.0}) {
          // Entries only: the path moves into the cell through face k.
          if (!(dir * g.bary_rate(g.interpolate(beta))[k] > 0)) continue;
          ++tried[type];
          ExitResult fast;
          if (!predicted_exit_local(local, beta, dir, fast)) continue;
          ++answered[type];
          const CellPath pw(world, x0, dir);
          const ExitResult ref = find_exit(g, pw, ExitParams{});
          ASSERT_EQ(ref.kind, ExitResult::exit);
          EXPECT_EQ(fast.face, ref.face) << "cell " << c;
          // The general search stops within eps_N tau_T of the root: short exits compare
          // on the cell's time scale.
          EXPECT_NEAR(fast.tau, ref.tau, 1e-10 * std::max(ref.tau, g.transit_time())) << "cell " << c;
          EXPECT_LE((g.point(fast.beta) - ref.x).norm(), 1e-10 * g.h_min) << "cell " << c;
          EXPECT_EQ(fast.beta[fast.face], 0.0);
          EXPECT_GE(fast.beta.minCoeff(), 0.0);
        }
      }
    }
  }
  for (CellType t : {CellType::normal_real, CellType::normal_complex}) {
    const int i = static_cast<int>(t);
    // Random vertex vectors make the field turn hard inside one cell: there most
    // declines are crossings longer than the step bound 0.25 / rate, which the bracket
    // search takes (declines on smooth data: the bench's evaluations per cell).
    EXPECT_GT(tried[i], 1000) << cell_type_name(t);
    EXPECT_GT(answered[i], 200) << cell_type_name(t) << ": " << answered[i] << " of " << tried[i];
  }
}

}  // namespace
