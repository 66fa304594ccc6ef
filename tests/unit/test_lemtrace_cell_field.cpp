// Cell classification and the eigen form (docs/lemtrace.md §1): the decomposition
// reconstructs A, Cardano's roots match Eigen's general eigensolver, det S = 1, and the
// cell types of fields whose structure is known by construction.

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "lemtrace/cell_field.hpp"
#include "lemtrace/closed_form.hpp"

namespace {

using namespace fest::lemtrace;

// A regular-ish tet around `centre` with vertex vectors A V + b.
TetMesh one_tet(const Mat3& A, const Vec3& b, const Vec3& centre, double size, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  TetMesh m;
  const Vec3 base[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (const Vec3& p : base) {
    const Vec3 x = centre + size * (p + Vec3(u(rng), u(rng), u(rng)));
    m.points.push_back(x);
    m.vectors.push_back(A * x + b);
  }
  m.tets.push_back({0, 1, 2, 3});
  if (signed_volume(m.points[0], m.points[1], m.points[2], m.points[3]) < 0) std::swap(m.tets[0][2], m.tets[0][3]);
  return m;
}

TEST(LemtraceCellField, EigenFormReconstructsRandomFields) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  int normal = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Mat3 A;
    for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = n(rng);
    const Vec3 b(n(rng), n(rng), n(rng));
    // Centre far from the critical point so that most cells are normal.
    const TetMesh m = one_tet(A, b, Vec3(5, 5, 5) + Vec3(n(rng), n(rng), n(rng)), 0.1, rng);
    const CellRecord r = classify(tet_geometry(m, 0), ClassifyParams{});

    // Cardano against Eigen's EigenSolver.
    double re[3], im[3];
    cubic_eigenvalues(A, re, im);
    Eigen::EigenSolver<Mat3> es(A);
    const auto ev = es.eigenvalues();
    const double scale = std::max(1.0, ev.cwiseAbs().maxCoeff());
    for (int i = 0; i < 3; ++i) {
      double best = 1e300;
      for (int j = 0; j < 3; ++j) best = std::min(best, std::abs(std::complex<double>(re[j], im[j]) - ev[i]));
      EXPECT_LE(best, 1e-9 * scale) << "trial " << trial;
    }
    if (r.type != CellType::normal_real && r.type != CellType::normal_complex) continue;
    ++normal;
    const Mat3 S = record_S(r), Sinv = record_Sinv(r);
    EXPECT_NEAR(S.determinant(), 1.0, 1e-9);
    EXPECT_LE((S * Sinv - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-9);
    Mat3 L = Mat3::Zero();
    if (r.type == CellType::normal_real) {
      L.diagonal() = Vec3(r.lam[0], r.lam[1], r.lam[2]);
    } else {
      L << r.lam[0], r.lam[1], 0, -r.lam[1], r.lam[0], 0, 0, 0, r.lam[2];
    }
    EXPECT_LE((S * L * Sinv - A).cwiseAbs().maxCoeff(), 1e-9 * A.cwiseAbs().maxCoeff()) << "trial " << trial;
  }
  EXPECT_GT(normal, 15000);
}

TEST(LemtraceCellField, KnownStructures) {
  std::mt19937_64 rng(3);
  Mat3 rot;
  rot << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  // Rotation about the z axis: a tet on the axis holds the critical line.
  CellRecord r = classify(tet_geometry(one_tet(rot, Vec3::Zero(), Vec3(0, 0, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::extraordinary);
  EXPECT_TRUE(r.critical_inside);
  // Off the axis it is a normal complex cell (eigenvalues 0, +-i).
  r = classify(tet_geometry(one_tet(rot, Vec3::Zero(), Vec3(0.6, 0, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::normal_complex);
  EXPECT_NEAR(r.lam[0], 0.0, 1e-12);
  EXPECT_NEAR(r.lam[1], 1.0, 1e-12);
  EXPECT_NEAR(r.lam[2], 0.0, 1e-12);
  // Helix: the axis is no critical line (z' = 0.05 everywhere).
  r = classify(tet_geometry(one_tet(rot, Vec3(0, 0, 0.05), Vec3(0, 0, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::normal_complex);
  EXPECT_FALSE(r.critical_inside);
  // Saddle with its rest point inside / outside.
  const Mat3 saddle = Vec3(1, -1, 0.5).asDiagonal();
  r = classify(tet_geometry(one_tet(saddle, Vec3::Zero(), Vec3(0.01, 0.02, 0.0), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::extraordinary);
  EXPECT_TRUE(r.critical_inside);
  r = classify(tet_geometry(one_tet(saddle, Vec3::Zero(), Vec3(0.5, 0.5, 0.5), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::normal_real);
  EXPECT_NEAR(r.lam[0], 1.0, 1e-12);
  EXPECT_NEAR(r.lam[1], 0.5, 1e-12);
  EXPECT_NEAR(r.lam[2], -1.0, 1e-12);
  // Shear and uniform flow: all vectors along x -> parallel.
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = 1;
  r = classify(tet_geometry(one_tet(shear, Vec3(0.2, 0, 0), Vec3(0.3, 0.3, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::parallel);
  EXPECT_NEAR(std::abs(r.lam[0]), 1.0, 1e-12);
  r = classify(tet_geometry(one_tet(Mat3::Zero(), Vec3(1, 2, 3), Vec3(0.3, 0.3, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::parallel);
  // Nilpotent but not rank 1 in direction: two zero eigenvalues, vectors not parallel.
  Mat3 nil = Mat3::Zero();
  nil(0, 1) = 1;
  nil(1, 2) = 1;
  r = classify(tet_geometry(one_tet(nil, Vec3(0, 0, 1), Vec3(0.3, 0.3, 0.3), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::extraordinary);
  // A defective (Jordan) block.
  Mat3 jordan;
  jordan << -0.3, 1, 0, 0, -0.3, 0, 0, 0, 0.2;
  r = classify(tet_geometry(one_tet(jordan, Vec3(0.1, 0.05, 0), Vec3(2, 2, 2), 0.1, rng), 0), ClassifyParams{});
  EXPECT_EQ(r.type, CellType::extraordinary);
}

TEST(LemtraceCellField, PsiIsSmoothAtZero) {
  EXPECT_DOUBLE_EQ(psi(0.0, 2.0), 2.0);
  for (double l : {1e-12, 1e-7, 1e-3, 0.5, -2.0})
    EXPECT_NEAR(psi(l, 0.7), std::expm1(l * 0.7) / l, 1e-15 * 0.7 + 1e-16) << l;
}

}  // namespace
