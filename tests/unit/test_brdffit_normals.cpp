#include "brdffit/normals.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "brdffit_test_data.hpp"

using namespace fest::brdffit;
using fest::reflectance::LafortuneBrdf;
using fest::reflectance::LafortuneLobe;
using fest::reflectance::Rgb;
using Eigen::Vector3d;

namespace {

double angle_deg(const Vector3d& a, const Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI;
}

// One-function projection: every lumitexel's BRDF is `brdf` with weight 1.
Projection single(const LafortuneBrdf& brdf, std::size_t n) {
  Projection p;
  p.basis.brdfs = {from_brdf(ModelSpec{}, brdf)};
  p.basis.cluster_basis = {{0}};
  p.basis_size = 1;
  p.cluster.assign(n, 0);
  p.weights.assign(n, 1.0f);
  return p;
}

// Lumitexels whose samples come from a true normal tilted away from the stored (mesh)
// normal by 5..12 degrees, like a bump map the mesh does not have; `lights` light
// directions per lumitexel, views random.
LumitexelSet bumped(const LafortuneBrdf& brdf, int count, int lights, unsigned seed, std::vector<Vector3d>& truth) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u01(0, 1);
  LumitexelSet set;
  for (int i = 0; i < count; ++i) {
    const Vector3d n0 = Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Eigen::Matrix3d f0 = fest::reflectance::local_frame(n0);
    const double tilt = (5 + 7 * u01(rng)) * M_PI / 180, az = 2 * M_PI * u01(rng);
    const Vector3d nt = (std::cos(tilt) * n0 + std::sin(tilt) * (std::cos(az) * f0.col(0) + std::sin(az) * f0.col(1))).normalized();
    const Eigen::Matrix3d ft = fest::reflectance::local_frame(nt);
    Lumitexel l;
    l.n = n0.cast<float>();
    l.first_sample = set.samples.size();
    l.count = static_cast<std::uint16_t>(lights);
    for (int k = 0; k < lights; ++k) {
      const Vector3d u = brdffit_test::hemisphere(rng, 0.2);
      const Vector3d v = (k % 2) ? brdffit_test::near_mirror(rng, u, 0.3, 0.2) : brdffit_test::hemisphere(rng, 0.2);
      Sample s;
      s.u_world = (ft * u).cast<float>();
      s.v_world = (ft * v).cast<float>();
      s.r = (evaluate(brdf, u, v) * u.z()).cast<float>();
      set.samples.push_back(s);
    }
    set.lumitexels.push_back(l);
    truth.push_back(nt);
  }
  return set;
}

}  // namespace

TEST(BrdffitNormals, DiffuseCaseEqualsClosedFormPhotometricStereo) {
  // docs/brdffit.md §7: with f = rho / pi and >= 3 lights, n = normalize((L^T L)^-1 L^T r).
  LafortuneBrdf diffuse;
  diffuse.rho_d = Rgb(0.6, 0.5, 0.4);
  diffuse.lobes = {LafortuneLobe{}};
  std::vector<Vector3d> truth;
  const LumitexelSet set = bumped(diffuse, 20, 8, 5, truth);
  const NormalResult r = refine_normals(set, single(diffuse, set.lumitexels.size()), NormalOptions{});
  ASSERT_EQ(r.refined_count, 20u);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Lumitexel& l = set.lumitexels[i];
    Eigen::MatrixXd lights(l.count, 3);
    Eigen::VectorXd rad(l.count);
    for (int k = 0; k < l.count; ++k) {
      lights.row(k) = set.samples[l.first_sample + static_cast<std::size_t>(k)].u_world.cast<double>().normalized().transpose();
      rad[k] = set.samples[l.first_sample + static_cast<std::size_t>(k)].r[1];
    }
    const Vector3d closed = (lights.transpose() * lights).ldlt().solve(lights.transpose() * rad).normalized();
    EXPECT_LT(angle_deg(r.normals[i].cast<double>(), closed), 1e-4) << i;  // 1e-4 deg ~ 2e-6 rad
    EXPECT_LT((r.normals[i].cast<double>() - closed).norm(), 1e-6 * 10) << i;
  }
  EXPECT_LT(r.residual_after, 1e-6 * r.residual_before);
}

TEST(BrdffitNormals, RefinedNormalsCloserToTheTruthThanMeshNormals) {
  // docs/brdffit.md §7: 8 lights -> median within 2 degrees of the truth vs >= 5 for the mesh.
  LafortuneBrdf glossy;
  glossy.rho_d = Rgb(0.5, 0.4, 0.3);
  glossy.lobes = {LafortuneLobe{Rgb::Constant(-1), Rgb::Constant(1), Rgb::Constant(30)}};
  std::vector<Vector3d> truth;
  LumitexelSet set = bumped(glossy, 200, 8, 9, truth);
  std::mt19937_64 rng(10);
  std::normal_distribution<double> g(0, 0.02);
  for (Sample& s : set.samples)
    for (int c = 0; c < 3; ++c) s.r[c] *= static_cast<float>(1 + g(rng));
  NormalOptions o;
  o.threads = 2;
  const NormalResult r = refine_normals(set, single(glossy, set.lumitexels.size()), o);
  std::vector<double> before, after;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    before.push_back(angle_deg(set.lumitexels[i].n.cast<double>(), truth[i]));
    after.push_back(angle_deg(r.normals[i].cast<double>(), truth[i]));
  }
  std::nth_element(before.begin(), before.begin() + 100, before.end());
  std::nth_element(after.begin(), after.begin() + 100, after.end());
  std::printf("median angle to the truth: mesh %.2f deg, refined %.2f deg\n", before[100], after[100]);
  EXPECT_GE(before[100], 5.0);
  EXPECT_LE(after[100], 2.0);
  EXPECT_LT(r.residual_after, r.residual_before);
}

TEST(BrdffitNormals, TiltIsBoundedAndFewSamplesAreLeftAlone) {
  LafortuneBrdf diffuse;
  diffuse.rho_d = Rgb::Constant(0.5);
  std::vector<Vector3d> truth;
  LumitexelSet set = bumped(diffuse, 10, 8, 12, truth);
  set.lumitexels[3].count = 4;  // below --normal-min-samples 5
  NormalOptions o;
  o.max_tilt_deg = 3;
  const NormalResult r = refine_normals(set, single(diffuse, set.lumitexels.size()), o);
  EXPECT_EQ(r.refined_count, 9u);
  EXPECT_EQ(r.refined[3], 0);
  for (std::size_t i = 0; i < truth.size(); ++i)
    EXPECT_LE(angle_deg(r.normals[i].cast<double>(), set.lumitexels[i].n.cast<double>()), 3.0 + 1e-3);
}
