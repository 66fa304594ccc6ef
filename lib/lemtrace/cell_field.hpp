#pragma once
// The linear field of one tetrahedron, its classification and the per-cell record of
// chapter 9 (§9.3.1-9.3.3; docs/lemtrace.md §1-4).
//
// Inside T the interpolated field is v(x) = A x + b with A = F E^{-1}, b = v0 - A V0.
// A cell is PARALLEL (all vectors along one direction: the path is a ray), NORMAL_REAL
// (three distinct real eigenvalues), NORMAL_COMPLEX (a conjugate pair and a real one),
// or EXTRAORDINARY (repeated or defective eigenvalues, ill-conditioned eigenvectors, or a
// critical point inside T), which the generic exponential form handles.

#include <cstdint>

#include <Eigen/Core>

#include "lemtrace/tet_mesh.hpp"

namespace fest::lemtrace {

using Mat3 = Eigen::Matrix3d;

enum class CellType : uint8_t { parallel = 0, normal_real = 1, normal_complex = 2, extraordinary = 3 };
const char* cell_type_name(CellType t) noexcept;

// Geometry of one tet, computed on each visit (cheap): barycentric coordinates are
// beta_{1..3} = G (x - V0), beta_0 = 1 - beta_1 - beta_2 - beta_3.
struct TetGeometry {
  Vec3 V[4];
  Vec3 v[4];       // vertex vectors
  Mat3 G;          // E^{-1}
  double h_min;    // shortest edge
  double v_max;    // largest vertex speed
  Eigen::Vector4d bary(const Vec3& x) const {
    Vec3 b = G * (x - V[0]);
    return {1.0 - b.sum(), b[0], b[1], b[2]};
  }
  // d(beta)/dt for a velocity w.
  Eigen::Vector4d bary_rate(const Vec3& w) const {
    Vec3 b = G * w;
    return {-b.sum(), b[0], b[1], b[2]};
  }
  Vec3 point(const Eigen::Vector4d& beta) const {
    return beta[0] * V[0] + beta[1] * V[1] + beta[2] * V[2] + beta[3] * V[3];
  }
  Vec3 interpolate(const Eigen::Vector4d& beta) const {
    return beta[0] * v[0] + beta[1] * v[1] + beta[2] * v[2] + beta[3] * v[3];
  }
  // The cell's time scale tau_T = h_T / max |v_k| (infinite for a field of zeros).
  double transit_time() const;
};

TetGeometry tet_geometry(const TetMesh& mesh, int32_t cell);

// The piecewise-linear field at x in `cell`: tet_geometry(...).interpolate(bary(x)),
// the same arithmetic, without the edge lengths and speeds (for the output's Speed and
// Velocity of every point).
Vec3 velocity_in_cell(const TetMesh& mesh, int32_t cell, const Vec3& x);

// A x + b of the cell.
void linear_field(const TetGeometry& g, Mat3& A, Vec3& b);

struct ClassifyParams {
  double eps_parallel = 1e-4;   // epsilon_P
  bool eps_relative = true;     // compare |lambda| tau_T (rel) or |lambda| (abs, the paper's)
  double eps_distinct = 1e-8;   // epsilon_E
  double max_condition = 1e8;   // eigenvector bases worse than this are extraordinary
};

// The per-cell record (docs/lemtrace.md §4). Plain data, trivially constructible, so that a lazy
// table of them costs memory only where pages are touched.
struct CellRecord {
  CellType type;
  bool critical_inside;
  // Normal cells only: true when S, S^{-1} and c are in barycentric coordinates (see
  // to_barycentric_frame); false for the world-frame form classify() returns.
  bool bary_frame;
  // bary_frame: the interpolated speed |v| is at least 2^speed_log2 everywhere in the cell
  // (INT8_MIN: no such bound), so that the tracer's terminal-speed test reads the vertex
  // vectors only in cells where the field may come near rest.
  int8_t speed_log2;
  // bary_frame: the cell's time scale in barycentric units, 1 / max_k |G v_k| (a float:
  // it sets sampling steps and round-off thresholds, never a position).
  float tau_bary;
  // normal_real: lambda_1..3. normal_complex: alpha, beta, lambda_3. parallel: unit d.
  double lam[3];
  // normal: S (row-major). parallel: a (speed gradient) in [0..2]. extraordinary: A.
  double S[9];
  // normal: S^{-1} (row-major). extraordinary: x_c in [0..2] when A is invertible.
  double Sinv[9];
  // normal: c = S^{-1} b. parallel: s0, mu = a.d. extraordinary: b.
  double c[3];
};

// 200 bytes: the flags and tau_bary share the first 8, so the speed bound costs nothing.
static_assert(sizeof(CellRecord) == 200, "the per-cell record of docs/lemtrace.md §4");

CellRecord classify(const TetGeometry& g, const ClassifyParams& params);

// Eigenvalues of a 3x3 matrix from its characteristic cubic (Cardano, one Newton step
// on each root). Returns true for three real roots (sorted descending in re[]), false for
// one real root re[2] and the pair re[0] +- i im[0] (im[0] > 0).
bool cubic_eigenvalues(const Mat3& A, double re[3], double im[3]);

// The same closed form in the cell's barycentric coordinates u = (beta_1, beta_2, beta_3)
// = G (x - V0), for normal cells (others are returned unchanged). The path there solves
// u' = (G A E) u + G v0; G A E = (G S) Lambda (S^{-1} E) has the same eigenvalues, so the
// record keeps lambda and stores S_u = G S, S_u^{-1} = S^{-1} E and c_u = S^{-1} v0. A
// path traced in u needs neither the vertices nor G: beta is u itself (beta_0 = 1 - sum),
// which is what makes a precomputed cell crossing cheaper than an Euler step (§9.4.4).
CellRecord to_barycentric_frame(const TetGeometry& g, const CellRecord& world);

Mat3 record_S(const CellRecord& r);
Mat3 record_Sinv(const CellRecord& r);

}  // namespace fest::lemtrace
