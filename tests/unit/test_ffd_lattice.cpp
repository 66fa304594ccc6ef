// lib/ffd: the exactness targets of docs/ffd.md section 5, each against mathematics: the
// identity, affine reproduction and det A volume ratio, the plain Sederberg-Parry sum,
// B-spline locality, the Jacobian against finite differences, exact joints with the
// minimal-norm property, the Kabsch fit, and the PyGeM .prm box computed by hand.

#include <cmath>
#include <array>
#include <random>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "ffd/joints.hpp"
#include "ffd/lattice.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"

namespace {

using namespace fest::ffd;
using Eigen::Vector3d;

Lattice box_lattice(Basis b, int L, int M, int N) {
  Lattice l;
  l.origin = Vector3d(-1, -2, 0.5);
  l.axes = {Vector3d(2, 0.3, 0), Vector3d(0.2, 3, 0.1), Vector3d(0, -0.4, 1.5)};  // skewed box
  l.dims = {L, M, N};
  l.basis.fill(b);
  l.displacement.assign(l.size(), Vector3d::Zero());
  return l;
}

std::vector<Vector3d> points_inside(const Lattice& l, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vector3d> p;
  for (int i = 0; i < n; ++i) p.push_back(l.origin + u(rng) * l.axes[0] + u(rng) * l.axes[1] + u(rng) * l.axes[2]);
  return p;
}

const Basis all_bases[] = {Basis::bernstein, Basis::bspline, Basis::linear, Basis::catmull_rom};

TEST(FfdLattice, ZeroDisplacementIsTheIdentity) {
  for (const Basis b : all_bases) {
    const Lattice l = box_lattice(b, 5, 4, 6);
    const Deformer d(l);
    for (const Vector3d& x : points_inside(l, 200, 1)) EXPECT_LE((d.apply(x) - x).norm(), 1e-14 * x.norm() + 1e-15) << basis_name(b);
  }
}

TEST(FfdLattice, AffineDisplacementReproducesTheAffineMap) {
  Eigen::Matrix3d A;
  A << 1.2, 0.3, -0.1, 0.05, 0.9, 0.2, -0.2, 0.1, 1.1;
  const Vector3d t(0.3, -0.7, 1.1);
  for (const Basis b : all_bases) {
    Lattice l = box_lattice(b, 6, 5, 7);
    for (int k = 0; k < l.dims[2]; ++k)
      for (int j = 0; j < l.dims[1]; ++j)
        for (int i = 0; i < l.dims[0]; ++i) {
          const Vector3d p0 = l.rest_point(i, j, k);
          l.displacement[l.index(i, j, k)] = A * p0 + t - p0;
        }
    const Deformer d(l);
    for (const Vector3d& x : points_inside(l, 300, 2)) {
      EXPECT_LE((d.apply(x) - (A * x + t)).norm(), 1e-12) << basis_name(b);
      // The Jacobian of an affine map is A everywhere, so det J = det A (volume ratio).
      EXPECT_NEAR(d.jacobian(x).determinant(), A.determinant(), 1e-12) << basis_name(b);
    }
  }
}

// Volume of a closed triangle mesh by the divergence theorem.
double volume(const std::vector<Vector3d>& v, const std::vector<std::array<int, 3>>& t) {
  double s = 0;
  for (const auto& f : t) s += v[f[0]].dot(v[f[1]].cross(v[f[2]])) / 6.0;
  return s;
}

TEST(FfdLattice, ClosedMeshVolumeScalesByDetA) {
  // An octahedron inside the box; an affine (Bernstein) lattice and a shear (det 1).
  Lattice l = box_lattice(Basis::bernstein, 4, 4, 4);
  const Vector3d c = l.origin + 0.5 * (l.axes[0] + l.axes[1] + l.axes[2]);
  std::vector<Vector3d> v = {c + Vector3d(0.3, 0, 0), c - Vector3d(0.3, 0, 0), c + Vector3d(0, 0.3, 0),
                             c - Vector3d(0, 0.3, 0), c + Vector3d(0, 0, 0.3), c - Vector3d(0, 0, 0.3)};
  const std::vector<std::array<int, 3>> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const double v0 = volume(v, t);
  ASSERT_GT(v0, 0);
  for (const bool shear : {false, true}) {
    Eigen::Matrix3d A;
    if (shear) A << 1, 0.4, 0, 0, 1, 0, 0, 0, 1;
    else A << 1.5, 0.1, 0, 0, 0.8, 0.2, 0.1, 0, 1.3;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const Vector3d p0 = l.rest_point(i, j, k);
          l.displacement[l.index(i, j, k)] = A * p0 - p0;
        }
    const Deformer d(l);
    std::vector<Vector3d> w;
    for (const Vector3d& x : v) w.push_back(d.apply(x));
    EXPECT_NEAR(volume(w, t) / v0, A.determinant(), 1e-12);
  }
}

TEST(FfdLattice, BernsteinEqualsThePlainSederbergParrySum) {
  // X' = sum_ijk C(l,i) C(m,j) C(n,k) s^i (1-s)^(l-i) ... P_ijk, written out directly.
  Lattice l = box_lattice(Basis::bernstein, 4, 3, 5);
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 0.2);
  for (auto& d : l.displacement) d = Vector3d(g(rng), g(rng), g(rng));
  const Deformer d(l);
  auto binom = [](int n, int k) { return std::tgamma(n + 1.0) / (std::tgamma(k + 1.0) * std::tgamma(n - k + 1.0)); };
  for (const Vector3d& x : points_inside(l, 100, 4)) {
    const Vector3d stu = d.local(x);
    Vector3d sum = Vector3d::Zero();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 5; ++k) {
          const double w = binom(3, i) * std::pow(stu[0], i) * std::pow(1 - stu[0], 3 - i) * binom(2, j) * std::pow(stu[1], j) *
                           std::pow(1 - stu[1], 2 - j) * binom(4, k) * std::pow(stu[2], k) * std::pow(1 - stu[2], 4 - k);
          sum += w * (l.rest_point(i, j, k) + l.displacement[l.index(i, j, k)]);
        }
    EXPECT_LE((d.apply(x) - sum).norm(), 1e-12);
  }
}

TEST(FfdLattice, PointsOnTheBoxFacesDeformAndOutsidePointsDoNot) {
  Lattice l = box_lattice(Basis::bernstein, 3, 3, 3);
  for (auto& d : l.displacement) d = Vector3d(0.1, 0.2, 0.3);  // a translation
  const Deformer d(l);
  const Vector3d corner = l.origin + l.axes[0] + l.axes[1] + l.axes[2];
  EXPECT_LE((d.apply(corner) - (corner + Vector3d(0.1, 0.2, 0.3))).norm(), 1e-12);
  const Vector3d face = l.origin + 0.3 * l.axes[1] + 0.6 * l.axes[2];
  EXPECT_LE((d.apply(face) - (face + Vector3d(0.1, 0.2, 0.3))).norm(), 1e-12);
  const Vector3d out = l.origin - 0.01 * l.axes[0];
  EXPECT_EQ(d.apply(out), out);
  EXPECT_LE((d.apply(out, Outside::clamp) - (out + Vector3d(0.1, 0.2, 0.3))).norm(), 1e-12);
}

TEST(FfdLattice, BsplineMovesOnlyWithinTheSupport) {
  Lattice l = box_lattice(Basis::bspline, 10, 10, 10);
  l.displacement[l.index(2, 2, 2)] = Vector3d(0, 0, 1);
  const Deformer d(l);
  // Clamped cubic, 10 points: 7 spans of width 1/7; point 2's support is knots t2..t6 = [0, 3/7].
  for (const Vector3d& x : points_inside(l, 500, 5)) {
    const Vector3d stu = d.local(x);
    const bool in_support = stu[0] < 3.0 / 7 && stu[1] < 3.0 / 7 && stu[2] < 3.0 / 7;
    if (!in_support) {
      EXPECT_EQ(d.apply(x), x);
    }
  }
}

TEST(FfdLattice, JacobianMatchesFiniteDifferences) {
  for (const Basis b : all_bases) {
    Lattice l = box_lattice(b, 5, 5, 5);
    std::mt19937 rng(6);
    std::normal_distribution<double> g(0, 0.3);
    for (auto& d : l.displacement) d = Vector3d(g(rng), g(rng), g(rng));
    const Deformer d(l);
    for (const Vector3d& x : points_inside(l, 50, 7)) {
      const Eigen::Matrix3d J = d.jacobian(x);
      const double h = 1e-6;
      Eigen::Matrix3d F;
      for (int a = 0; a < 3; ++a) F.col(a) = (d.apply(x + h * Vector3d::Unit(a)) - d.apply(x - h * Vector3d::Unit(a))) / (2 * h);
      // Points within h of a knot plane see a one-sided kink for linear/catmull-rom (C0/C1).
      EXPECT_LE((J - F).norm(), b == Basis::linear ? 1.0 : 1e-6) << basis_name(b);
    }
  }
}

TEST(FfdJoints, JointsLandOnTheirTargetsWithTheSmallestCorrection) {
  for (const Basis b : {Basis::bernstein, Basis::bspline}) {
    for (const int C : {1, 5, 20}) {
      Lattice l = box_lattice(b, 5, 5, 6);
      std::mt19937 rng(static_cast<unsigned>(C));
      std::normal_distribution<double> g(0, 0.2);
      for (auto& d : l.displacement) d = Vector3d(g(rng), g(rng), g(rng));
      const Lattice before = l;
      std::vector<Joint> joints;
      const auto rest = points_inside(l, C, 11);
      const auto targets = points_inside(l, C, 12);
      for (int c = 0; c < C; ++c) joints.push_back({"j" + std::to_string(c), rest[c], targets[c]});
      const JointSolve s = preserve_joints(l, joints);
      const double size = l.axes[0].norm() + l.axes[1].norm() + l.axes[2].norm();
      EXPECT_TRUE(s.exact);
      EXPECT_LE(s.max_error_after, 1e-9 * size) << basis_name(b) << " " << C;
      const Deformer d(l);
      for (const Joint& j : joints) EXPECT_LE((d.apply(j.rest) - j.target).norm(), 1e-9 * size);
      // Minimal norm: delta lies in the row space of W, so adding any null-space vector
      // keeps feasibility and makes the correction larger.
      double dn = 0;
      for (std::size_t k = 0; k < l.size(); ++k) dn += (l.displacement[k] - before.displacement[k]).squaredNorm();
      EXPECT_NEAR(std::sqrt(dn), s.correction_norm, 1e-12 * (1 + s.correction_norm));
    }
  }
}

TEST(FfdJoints, FixedControlPointsKeepTheirDisplacement) {
  Lattice l = box_lattice(Basis::bernstein, 4, 4, 4);
  std::vector<Joint> joints = {{"a", l.origin + 0.5 * (l.axes[0] + l.axes[1] + l.axes[2]),
                                l.origin + 0.5 * (l.axes[0] + l.axes[1] + l.axes[2]) + Vector3d(0.1, 0, 0)}};
  const std::vector<std::size_t> fixed = {l.index(1, 1, 1), l.index(2, 2, 2)};
  preserve_joints(l, joints, fixed);
  EXPECT_EQ(l.displacement[l.index(1, 1, 1)], Vector3d::Zero());
  EXPECT_EQ(l.displacement[l.index(2, 2, 2)], Vector3d::Zero());
  EXPECT_LE((Deformer(l).apply(joints[0].rest) - joints[0].target).norm(), 1e-9);
}

TEST(FfdJoints, JointOutsideTheBoxIsBadInput) {
  Lattice l = box_lattice(Basis::bernstein, 3, 3, 3);
  std::vector<Joint> joints = {{"far", Vector3d(100, 100, 100), Vector3d(0, 0, 0)}};
  try {
    preserve_joints(l, joints);
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
  }
}

TEST(FfdRigid, KabschRecoversARotation) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3d t(1, -2, 0.5);
  std::vector<Vector3d> a, b;
  std::mt19937 rng(9);
  std::normal_distribution<double> g(0, 1);
  for (int i = 0; i < 50; ++i) {
    a.emplace_back(g(rng), g(rng), g(rng));
    b.push_back(R * a.back() + t);
  }
  const RigidFit f = fit_rigid(a, b);
  EXPECT_LE((f.rotation - R).norm(), 1e-12);
  EXPECT_LE((f.translation - t).norm(), 1e-12);
  EXPECT_LE(f.rms, 1e-12);
}

TEST(FfdCodec, PygemBoxIsRxRyRzTimesLengths) {
  const std::string prm =
      "[Box info]\n"
      "# comment\n"
      "n control points x: 2\nn control points y: 2\nn control points z: 2\n"
      "box length x: 2.0\nbox length y: 1.0\nbox length z: 3.0\n"
      "box origin x: 0.5\nbox origin y: -1\nbox origin z: 0\n"
      "rotation angle x: 30\nrotation angle y: 0\nrotation angle z: 90\n"
      "\n[Parameters weights]\n"
      "parameter x: 1 1 1 0.25\n"
      "             0 0 0 0.0\n"
      "parameter y: 1 0 0 -0.5\n";
  const Lattice l = decode_pygem_prm(prm);
  // Rx(30) Rz(90): columns Rx*(0,1,0), Rx*(-1,0,0), Rx*(0,0,1).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  EXPECT_LE((l.axes[0] - 2.0 * Vector3d(0, c, s)).norm(), 1e-12);
  EXPECT_LE((l.axes[1] - 1.0 * Vector3d(-1, 0, 0)).norm(), 1e-12);
  EXPECT_LE((l.axes[2] - 3.0 * Vector3d(0, -s, c)).norm(), 1e-12);
  EXPECT_LE((l.origin - Vector3d(0.5, -1, 0)).norm(), 0);
  // mu is in box lengths along the box's own axes.
  EXPECT_LE((l.displacement[l.index(1, 1, 1)] - 0.25 * l.axes[0]).norm(), 1e-12);
  EXPECT_LE((l.displacement[l.index(1, 0, 0)] + 0.5 * l.axes[1]).norm(), 1e-12);
  // Round trip through the encoder.
  const Lattice back = decode_pygem_prm(encode_pygem_prm(l));
  for (int a = 0; a < 3; ++a) EXPECT_LE((back.axes[a] - l.axes[a]).norm(), 1e-12);
  for (std::size_t k = 0; k < l.size(); ++k) EXPECT_LE((back.displacement[k] - l.displacement[k]).norm(), 1e-12);
}

TEST(FfdCodec, JsonRoundTripAndErrors) {
  Lattice l = box_lattice(Basis::bspline, 3, 4, 5);
  l.basis[2] = Basis::linear;
  l.displacement[l.index(2, 3, 4)] = Vector3d(0.1, 0.2, 0.3);
  const Lattice back = decode_lattice_json(encode_lattice_json(l));
  EXPECT_EQ(back.dims, l.dims);
  EXPECT_EQ(back.basis, l.basis);
  EXPECT_EQ(back.displacement, l.displacement);
  for (const char* bad : {"", "{", "[]", R"({"origin":[0,0,0],"axes":[[1,0,0],[0,1,0],[0,0,1]],"dims":[1,2,2]})",
                          R"({"origin":[0,0,0],"axes":[[1,0,0],[2,0,0],[0,0,1]],"dims":[2,2,2]})",
                          R"({"origin":[0,0,0],"axes":[[1,0,0],[0,1,0],[0,0,1]],"dims":[2,2,2],"displacements":[[2,0,0,1,1,1]]})",
                          R"({"origin":[0,0,0],"axes":[[1,0,0],[0,1,0],[0,0,1]],"dims":[2,2,2],"basis":"cubic"})"}) {
    try {
      decode_lattice_json(bad);
      ADD_FAILURE() << bad;
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input) << bad;
    }
  }
  EXPECT_THROW(decode_joints("a 1 2 3 4 5\n"), fest::Error);
  EXPECT_EQ(decode_joints("name x y z tx ty tz\n# c\nj1 0 0 0 1 1 1\n").size(), 1u);
}

}  // namespace
