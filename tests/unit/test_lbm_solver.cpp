// The solver on small lattices: periodic streaming, Guo force, slab decomposition in one
// process (ranks as threads) bit-identical to one slab, moving-wall mass balance.
#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <thread>

#include "lbm/geometry.hpp"
#include "lbm/solver.hpp"

namespace fest::lbm {
namespace {

Case periodic_case(int dim, int n) {
  Case c;
  c.dim = dim;
  c.lattice = dim == 2 ? LatticeKind::d2q9 : LatticeKind::d3q19;
  c.size = {n, n + 1, dim == 3 ? n + 2 : 1};
  c.collision.tau = 0.8;
  return c;
}

std::unique_ptr<Solver> make(const Case& c, const Flags& f, InitFunction init = {}, SlabExchange* ex = nullptr,
                             int lo = 0, int hi = -1) {
  SolverSetup s;
  s.c = &c;
  s.flags = &f;
  s.init = std::move(init);
  s.exchange = ex;
  s.slab_lo = lo;
  s.slab_hi = hi;
  return make_solver(s);
}

TEST(LbmSolver, UniformForceAcceleratesAtFOverRho) {
  // Galilean test: a periodic box under a uniform force gains F/rho per step.
  for (int dim : {2, 3}) {
    Case c = periodic_case(dim, 6);
    c.force = {1e-5, -2e-5, dim == 3 ? 3e-5 : 0.0};
    const Flags f = shape_flags(c);
    auto s = make(c, f);
    for (int t = 0; t < 10; ++t) s->step();
    std::vector<double> rho, u;
    s->moments(rho, u);
    for (std::size_t k = 0; k < rho.size(); ++k)
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(u[3 * k + a], 10 * c.force[a] - 0.5 * c.force[a] + 0.5 * c.force[a], 1e-13);
  }
}

TEST(LbmSolver, PeriodicStreamingConservesMassExactly) {
  Case c = periodic_case(3, 8);
  c.collision.model = CollisionModel::trt;
  const Flags f = shape_flags(c);
  auto s = make(c, f, [](int x, int y, int z, double& rho, std::array<double, 3>& u) {
    rho = 1 + 0.01 * std::sin(x + 2 * y + 3 * z);
    u = {0.02 * std::cos(y), 0.01 * std::sin(z), 0.03 * std::cos(x)};
  });
  double m0 = 0;
  for (double v : s->layer_mass()) m0 += v;
  for (int t = 0; t < 50; ++t) s->step();
  double m1 = 0;
  for (double v : s->layer_mass()) m1 += v;
  EXPECT_NEAR(m1, m0, 1e-12 * m0);
}

// Ranks as threads: the slabs meet in shared slots behind a barrier.
class ThreadGroup {
 public:
  explicit ThreadGroup(int n) : n_(n), lo_(n), hi_(n), vec_(n) {}
  void barrier() {
    std::unique_lock<std::mutex> lock(m_);
    const long gen = gen_;
    if (++count_ == n_) {
      count_ = 0;
      ++gen_;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return gen_ != gen; });
    }
  }
  int n_;
  std::vector<std::vector<char>> lo_, hi_;
  std::vector<std::vector<double>> vec_;

 private:
  std::mutex m_;
  std::condition_variable cv_;
  int count_ = 0;
  long gen_ = 0;
};

class ThreadExchange final : public SlabExchange {
 public:
  ThreadExchange(ThreadGroup& g, int rank) : g_(g), rank_(rank) {}
  int rank() const override { return rank_; }
  int ranks() const override { return g_.n_; }
  void exchange(const void* to_lower, const void* to_upper, void* from_lower, void* from_upper, std::size_t bytes,
                bool periodic) override {
    g_.lo_[rank_].assign(static_cast<const char*>(to_lower), static_cast<const char*>(to_lower) + bytes);
    g_.hi_[rank_].assign(static_cast<const char*>(to_upper), static_cast<const char*>(to_upper) + bytes);
    g_.barrier();
    const int lower = rank_ > 0 ? rank_ - 1 : (periodic ? g_.n_ - 1 : -1);
    const int upper = rank_ + 1 < g_.n_ ? rank_ + 1 : (periodic ? 0 : -1);
    if (lower >= 0) std::memcpy(from_lower, g_.hi_[lower].data(), bytes);
    if (upper >= 0) std::memcpy(from_upper, g_.lo_[upper].data(), bytes);
    g_.barrier();
  }
  std::vector<double> allgather(const std::vector<double>& local) override {
    g_.vec_[rank_] = local;
    g_.barrier();
    std::vector<double> all;
    for (const auto& v : g_.vec_) all.insert(all.end(), v.begin(), v.end());
    g_.barrier();
    return all;
  }
  double max(double local) override {
    const auto all = allgather({local});
    double m = all[0];
    for (double v : all) m = std::max(m, v);
    return m;
  }

 private:
  ThreadGroup& g_;
  int rank_;
};

Case busy_case(int dim) {
  // Walls, a lid, an inlet and an outlet, an obstacle, a body force and a periodic axis.
  Case c;
  c.dim = dim;
  c.lattice = dim == 2 ? LatticeKind::d2q9 : LatticeKind::d3q19;
  c.size = {14, 11, dim == 3 ? 9 : 1};
  c.collision.model = CollisionModel::trt;
  c.collision.tau = 0.62;
  c.faces[0].kind = Face::Kind::velocity;
  c.faces[0].speed = 0.04;
  c.faces[0].profile = Face::Profile::parabolic;
  c.faces[1].kind = Face::Kind::pressure;
  c.faces[2].kind = Face::Kind::wall;
  c.faces[3].kind = Face::Kind::moving;
  c.faces[3].u = {0.03, 0, 0};
  if (dim == 3) c.faces[4].kind = c.faces[5].kind = Face::Kind::periodic;
  Shape s;
  s.kind = Shape::Kind::sphere;
  s.center = {5, 5, 4};
  s.radius = 2.5;
  c.shapes.push_back(s);
  c.force = {0, -1e-5, dim == 3 ? 2e-5 : 0};
  return c;
}

void run_decomposed(const Case& c, int ranks, int steps, std::vector<double>& rho, std::vector<double>& u,
                    std::vector<double>& force) {
  const Flags f = shape_flags(c);
  const std::vector<int> starts = slab_starts(c.size[c.dim - 1], ranks);
  ThreadGroup group(ranks);
  std::vector<std::vector<double>> r(ranks), v(ranks), fr(ranks);
  std::vector<std::thread> threads;
  for (int k = 0; k < ranks; ++k)
    threads.emplace_back([&, k] {
      ThreadExchange ex(group, k);
      auto s = make(c, f, {}, &ex, starts[k], starts[k + 1]);
      for (int t = 0; t < steps; ++t) s->step();
      s->moments(r[k], v[k]);
      fr[k] = s->layer_force(1);
    });
  for (auto& t : threads) t.join();
  rho.clear(), u.clear(), force.clear();
  for (int k = 0; k < ranks; ++k) {
    rho.insert(rho.end(), r[k].begin(), r[k].end());
    u.insert(u.end(), v[k].begin(), v[k].end());
    force.insert(force.end(), fr[k].begin(), fr[k].end());
  }
}

TEST(LbmSolver, SlabsGiveTheSameBitsAsOneSlab) {
  for (int variant = 0; variant < 3; ++variant)
  for (int dim : {2, 3}) {
    // 1: interpolated (Bouzidi) walls on the sphere, whose links next to a cut read the
    // neighbour slab's populations; 2: also the incompressible equilibrium.
    Case c = busy_case(dim);
    c.bouzidi = variant >= 1;
    c.collision.incompressible = variant == 2;
    std::vector<double> r1, u1, f1;
    run_decomposed(c, 1, 60, r1, u1, f1);
    for (int ranks : {2, 3, 4}) {
      std::vector<double> r, u, f;
      run_decomposed(c, ranks, 60, r, u, f);
      ASSERT_EQ(r.size(), r1.size());
      EXPECT_EQ(0, std::memcmp(r.data(), r1.data(), r.size() * sizeof(double))) << dim << "D, " << ranks << " ranks, variant " << variant;
      EXPECT_EQ(0, std::memcmp(u.data(), u1.data(), u.size() * sizeof(double))) << dim << "D, " << ranks << " ranks, variant " << variant;
      EXPECT_EQ(0, std::memcmp(f.data(), f1.data(), f.size() * sizeof(double))) << dim << "D, " << ranks << " ranks, variant " << variant;
    }
  }
}

TEST(LbmSolver, SlabStartsSplitUnevenCounts) {
  EXPECT_EQ(slab_starts(10, 4), (std::vector<int>{0, 3, 6, 8, 10}));
  EXPECT_EQ(slab_starts(4, 4), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(LbmSolver, RestingObstacleFeelsNoForce) {
  Case c = periodic_case(2, 20);
  Shape s;
  s.kind = Shape::Kind::cylinder;
  s.center = {10, 10, 0};
  s.radius = 4;
  c.shapes.push_back(s);
  const Flags f = shape_flags(c);
  auto solver = make(c, f);
  for (int t = 0; t < 5; ++t) solver->step();
  const auto F = solver->layer_force(1);
  double fx = 0, fy = 0;
  for (std::size_t l = 0; l < F.size() / 3; ++l) fx += F[3 * l], fy += F[3 * l + 1];
  EXPECT_NEAR(fx, 0.0, 1e-14);
  EXPECT_NEAR(fy, 0.0, 1e-14);
}

// Where the wall cuts a link (Bouzidi et al. 2001): the root of |p + q c - centre| = r,
// worked by hand for links whose answer is a closed form.
TEST(LbmGeometry, LinkFractionOnACircleIsTheAnalyticRoot) {
  Case c = periodic_case(2, 20);
  Shape s;
  s.kind = Shape::Kind::cylinder;
  s.center = {10, 10.5, 0};
  s.radius = 3;
  c.shapes.push_back(s);
  // Along -x from (13.5, 10.5): the surface is at x = 13, half the link.
  EXPECT_DOUBLE_EQ(link_fraction(c, {13.5, 10.5, 0}, {-1, 0, 0}), 0.5);
  // Along (-1, -1): (3.5 - q)^2 + q^2 = 9, q = (7 - sqrt 23) / 4.
  EXPECT_NEAR(link_fraction(c, {13.5, 10.5, 0}, {-1, -1, 0}), (7 - std::sqrt(23.0)) / 4, 1e-15);
  // Along +y from (10.5, 7.5): (10.5-10)^2 + (7.5 + q - 10.5)^2 = 9, q = 3 - sqrt 8.75.
  EXPECT_NEAR(link_fraction(c, {10.5, 7.5, 0}, {0, 1, 0}), 3 - std::sqrt(8.75), 1e-15);
  // Links that end in the fluid, leave the circle or point away: no fraction.
  EXPECT_EQ(link_fraction(c, {15.5, 10.5, 0}, {-1, 0, 0}), -1);  // ends at 14.5, outside
  EXPECT_EQ(link_fraction(c, {10.5, 10.5, 0}, {1, 0, 0}), -1);   // starts inside
  EXPECT_EQ(link_fraction(c, {13.5, 10.5, 0}, {1, 0, 0}), -1);   // points away
}

TEST(LbmGeometry, LinkFractionOnSphereAndCylinderIn3D) {
  Case c = periodic_case(3, 20);
  Shape sph;
  sph.kind = Shape::Kind::sphere;
  sph.center = {0, 0, 0};
  sph.radius = 2;
  c.shapes.push_back(sph);
  // (2.5 - q)^2 + 0.25 + 0.25 = 4.
  EXPECT_NEAR(link_fraction(c, {2.5, 0.5, 0.5}, {-1, 0, 0}), 2.5 - std::sqrt(3.5), 1e-15);
  // A cylinder along z ignores the z part of the link: (12.5 - q - 10)^2 + 0.25 = 4.
  Shape cyl;
  cyl.kind = Shape::Kind::cylinder;
  cyl.axis = 2;
  cyl.center = {10, 0, 0};
  cyl.radius = 2;
  c.shapes.push_back(cyl);
  EXPECT_NEAR(link_fraction(c, {12.5, 0.5, 7.5}, {-1, 0, -1}), 2.5 - std::sqrt(3.75), 1e-15);
  // A link along the axis never meets the mantle.
  EXPECT_EQ(link_fraction(c, {10.5, 0.5, 7.5}, {0, 0, 1}), -1);
  // Two shapes: the nearer crossing counts.
  Shape near;
  near.kind = Shape::Kind::sphere;
  near.center = {2.5, 0.5, 0.5 + 1.5};
  near.radius = 1.2;  // reached from (2.5, 0.5, 0.5) along +z at q = 0.3
  c.shapes.push_back(near);
  EXPECT_NEAR(link_fraction(c, {2.5, 0.5, 0.5}, {0, 0, 1}), 0.3, 1e-15);
  // Boxes carry no fraction (staircase walls).
  Case b = periodic_case(2, 20);
  Shape box;
  box.lo = {0, 0, -1e300};
  box.hi = {5, 5, 1e300};
  b.shapes.push_back(box);
  EXPECT_EQ(link_fraction(b, {5.5, 2.5, 0}, {-1, 0, 0}), -1);
}

}  // namespace
}  // namespace fest::lbm
