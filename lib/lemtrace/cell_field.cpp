#include "lemtrace/cell_field.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace fest::lemtrace {

const char* cell_type_name(CellType t) noexcept {
  switch (t) {
    case CellType::parallel: return "parallel";
    case CellType::normal_real: return "normal_real";
    case CellType::normal_complex: return "normal_complex";
    case CellType::extraordinary: return "extraordinary";
  }
  return "unknown";
}

double TetGeometry::transit_time() const {
  return v_max > 0 ? h_min / v_max : std::numeric_limits<double>::infinity();
}

namespace {

// What bary() and interpolate() need: the vertices, their vectors and G = E^{-1}.
inline void tet_frame(const TetMesh& mesh, int32_t cell, TetGeometry& g) {
  const Tet& t = mesh.tets[static_cast<std::size_t>(cell)];
  for (int k = 0; k < 4; ++k) {
    g.V[k] = mesh.points[static_cast<std::size_t>(t[k])];
    g.v[k] = mesh.vectors[static_cast<std::size_t>(t[k])];
  }
  const Vec3 e1 = g.V[1] - g.V[0], e2 = g.V[2] - g.V[0], e3 = g.V[3] - g.V[0];
  // Rows of E^{-1} are the cross products of the other two columns over det E.
  const Vec3 r1 = e2.cross(e3), r2 = e3.cross(e1), r3 = e1.cross(e2);
  const double inv_det = 1.0 / e1.dot(r1);
  g.G.row(0) = r1.transpose() * inv_det;
  g.G.row(1) = r2.transpose() * inv_det;
  g.G.row(2) = r3.transpose() * inv_det;
}

}  // namespace

Vec3 velocity_in_cell(const TetMesh& mesh, int32_t cell, const Vec3& x) {
  TetGeometry g;
  tet_frame(mesh, cell, g);
  return g.interpolate(g.bary(x));
}

TetGeometry tet_geometry(const TetMesh& mesh, int32_t cell) {
  TetGeometry g;
  tet_frame(mesh, cell, g);
  const Vec3 e1 = g.V[1] - g.V[0], e2 = g.V[2] - g.V[0], e3 = g.V[3] - g.V[0];
  double h2 = std::min({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm(), (g.V[2] - g.V[1]).squaredNorm(),
                        (g.V[3] - g.V[1]).squaredNorm(), (g.V[3] - g.V[2]).squaredNorm()});
  g.h_min = std::sqrt(h2);
  double v2 = 0;
  for (int k = 0; k < 4; ++k) v2 = std::max(v2, g.v[k].squaredNorm());
  g.v_max = std::sqrt(v2);
  return g;
}

void linear_field(const TetGeometry& g, Mat3& A, Vec3& b) {
  Mat3 F;
  F.col(0) = g.v[1] - g.v[0];
  F.col(1) = g.v[2] - g.v[0];
  F.col(2) = g.v[3] - g.v[0];
  A = F * g.G;
  b = g.v[0] - A * g.V[0];
}

namespace {

double cubic(double l, double tr, double m2, double det) { return ((l - tr) * l + m2) * l - det; }
double cubic_slope(double l, double tr, double m2) { return (3 * l - 2 * tr) * l + m2; }

double refine(double l, double tr, double m2, double det) {
  double f = cubic(l, tr, m2, det), d = cubic_slope(l, tr, m2);
  if (d == 0 || !std::isfinite(f / d)) return l;
  double next = l - f / d;
  return std::abs(cubic(next, tr, m2, det)) <= std::abs(f) ? next : l;
}

Vec3 largest_cross(const Mat3& M) {
  Vec3 c[3] = {M.row(0).cross(M.row(1)), M.row(1).cross(M.row(2)), M.row(2).cross(M.row(0))};
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (c[i].squaredNorm() > c[best].squaredNorm()) best = i;
  return c[best];
}

using C = std::complex<double>;
using CVec = Eigen::Matrix<C, 3, 1>;

CVec complex_cross(const CVec& a, const CVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

void store(const Mat3& M, double out[9]) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = M(r, c);
}

bool bary_inside(const TetGeometry& g, const Vec3& x, double eps) {
  Eigen::Vector4d b = g.bary(x);
  return b.minCoeff() >= -eps;
}

// Is any point of { S z : z_i = zc_i for fixed i, z_j free } inside the tet? At most one
// free coordinate is handled exactly; more are reported as inside (conservative).
bool critical_set_inside(const TetGeometry& g, const Mat3& S, Vec3 zc, const bool free_dim[3]) {
  int n_free = free_dim[0] + free_dim[1] + free_dim[2];
  const double eps_in = 1e-12;
  if (n_free == 0) return bary_inside(g, S * zc, eps_in);
  if (n_free > 1) return true;
  int j = free_dim[0] ? 0 : (free_dim[1] ? 1 : 2);
  zc[j] = 0;
  // beta(s) = p + s q along the line x(s) = S zc + s S e_j; clip against beta_k >= 0.
  Eigen::Vector4d p = g.bary(S * zc);
  Eigen::Vector4d q = g.bary_rate(S.col(j));
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    if (q[k] > 0) lo = std::max(lo, (-eps_in - p[k]) / q[k]);
    else if (q[k] < 0) hi = std::min(hi, (-eps_in - p[k]) / q[k]);
    else if (p[k] < -eps_in) return false;
  }
  return lo <= hi;
}

CellRecord extraordinary(const TetGeometry& g, const Mat3& A, const Vec3& b, bool critical_inside) {
  CellRecord r{};
  r.type = CellType::extraordinary;
  store(A, r.S);
  r.c[0] = b[0], r.c[1] = b[1], r.c[2] = b[2];
  const double norm = A.cwiseAbs().maxCoeff();
  const double det = A.determinant();
  if (norm > 0 && std::abs(det) > 1e-12 * norm * norm * norm) {
    Vec3 xc = -A.inverse() * b;
    r.Sinv[0] = xc[0], r.Sinv[1] = xc[1], r.Sinv[2] = xc[2];
    critical_inside = critical_inside || bary_inside(g, xc, 1e-12);
  } else {
    r.Sinv[0] = r.Sinv[1] = r.Sinv[2] = std::numeric_limits<double>::quiet_NaN();
  }
  r.critical_inside = critical_inside;
  return r;
}

}  // namespace

bool cubic_eigenvalues(const Mat3& A, double re[3], double im[3]) {
  const double tr = A.trace();
  const double m2 = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0) + A(0, 0) * A(2, 2) - A(0, 2) * A(2, 0) +
                    A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1);
  const double det = A.determinant();
  // lambda = t + tr/3 turns the cubic into t^3 + p t + q = 0.
  const double p = m2 - tr * tr / 3.0;
  const double q = -2.0 * tr * tr * tr / 27.0 + tr * m2 / 3.0 - det;
  const double disc = q * q / 4.0 + p * p * p / 27.0;
  im[0] = im[1] = im[2] = 0;
  if (disc <= 0) {
    const double r = std::sqrt(std::max(0.0, -p / 3.0));
    double t[3] = {0, 0, 0};
    if (r > 0) {
      const double phi = std::acos(std::clamp(-q / (2.0 * r * r * r), -1.0, 1.0));
      for (int k = 0; k < 3; ++k) t[k] = 2.0 * r * std::cos((phi - 2.0 * M_PI * k) / 3.0);
    }
    for (int k = 0; k < 3; ++k) re[k] = refine(t[k] + tr / 3.0, tr, m2, det);
    std::sort(re, re + 3, [](double a, double b) { return a > b; });
    return true;
  }
  // One real root: u = cbrt(-q/2 -+ sqrt(disc)) with the sign that avoids cancellation,
  // v = -p / (3u) since u v = -p/3.
  const double s = std::sqrt(disc);
  const double u = std::cbrt(-q / 2.0 - std::copysign(s, q));
  const double v = u != 0 ? -p / (3.0 * u) : 0.0;
  const double real_root = refine(u + v + tr / 3.0, tr, m2, det);
  // The pair: sum = tr - r, product = m2 - r * sum.
  const double sum = tr - real_root;
  const double prod = m2 - real_root * sum;
  const double alpha = sum / 2.0;
  re[0] = re[1] = alpha;
  re[2] = real_root;
  im[0] = std::sqrt(std::max(0.0, prod - alpha * alpha));
  im[1] = -im[0];
  return false;
}

Mat3 record_S(const CellRecord& r) {
  Mat3 S;
  for (int i = 0; i < 9; ++i) S(i / 3, i % 3) = r.S[i];
  return S;
}

Mat3 record_Sinv(const CellRecord& r) {
  Mat3 S;
  for (int i = 0; i < 9; ++i) S(i / 3, i % 3) = r.Sinv[i];
  return S;
}

CellRecord to_barycentric_frame(const TetGeometry& g, const CellRecord& world) {
  if (world.type != CellType::normal_real && world.type != CellType::normal_complex) return world;
  CellRecord r = world;
  Mat3 E;
  E.col(0) = g.V[1] - g.V[0];
  E.col(1) = g.V[2] - g.V[0];
  E.col(2) = g.V[3] - g.V[0];
  const Mat3 S = record_S(world), Sinv = record_Sinv(world);
  store(g.G * S, r.S);
  store(Sinv * E, r.Sinv);
  const Vec3 c = Sinv * g.v[0];
  r.c[0] = c[0], r.c[1] = c[1], r.c[2] = c[2];
  double rate2 = 0;
  for (int k = 0; k < 4; ++k) rate2 = std::max(rate2, (g.G * g.v[k]).squaredNorm());
  // Clamped into float range: a finite time scale stays finite (only a field of zeros,
  // which is never a normal cell, has none).
  r.tau_bary = rate2 > 0 ? static_cast<float>(std::min(1.0 / std::sqrt(rate2), double{std::numeric_limits<float>::max()}))
                         : std::numeric_limits<float>::infinity();
  r.bary_frame = true;
  // Lower bound of |v| over the cell: along the unit mean direction d of the vertex
  // vectors, v(x).d = sum beta_k (v_k.d) >= min_k v_k.d for any point of the cell (less a
  // margin for entry points a round-off outside). Kept as a power of two rounded down.
  r.speed_log2 = std::numeric_limits<int8_t>::min();
  const Vec3 sum = g.v[0] + g.v[1] + g.v[2] + g.v[3];
  const double sum_norm = sum.norm();
  if (sum_norm > 0 && std::isfinite(sum_norm)) {
    const Vec3 d = sum / sum_norm;
    double low = std::numeric_limits<double>::infinity(), high = 0;
    for (int k = 0; k < 4; ++k) {
      low = std::min(low, g.v[k].dot(d));
      high = std::max(high, g.v[k].norm());
    }
    low -= 1e-9 * high;
    if (low > 0 && std::isfinite(low)) {
      int e;
      std::frexp(low, &e);  // low >= 2^(e-1)
      if (e - 1 >= -127) r.speed_log2 = static_cast<int8_t>(std::min(e - 1, 127));
    }
  }
  return r;
}

CellRecord classify(const TetGeometry& g, const ClassifyParams& params) {
  Mat3 A;
  Vec3 b;
  linear_field(g, A, b);
  const double tauT = g.transit_time();

  if (!(g.v_max > 0)) {
    // A field of zeros: a parallel cell whose speed is zero everywhere (stagnation).
    CellRecord r{};
    r.type = CellType::parallel;
    r.lam[0] = 1;
    return r;
  }

  double re[3], im[3];
  const bool all_real = cubic_eigenvalues(A, re, im);
  const double eps_scale = params.eps_relative ? tauT : 1.0;
  int small = 0;
  for (int i = 0; i < 3; ++i)
    if (std::hypot(re[i], im[i]) * eps_scale < params.eps_parallel) ++small;

  if (small >= 2) {
    // Parallel only if the vertex vectors really lie along one direction: the second
    // singular value of [v0 v1 v2 v3] is small against the first.
    Mat3 gram = Mat3::Zero();
    for (int k = 0; k < 4; ++k) gram += g.v[k] * g.v[k].transpose();
    Eigen::SelfAdjointEigenSolver<Mat3> es;
    es.computeDirect(gram);
    const Vec3 mu = es.eigenvalues();
    if (mu[1] <= params.eps_parallel * params.eps_parallel * mu[2]) {
      Vec3 d = es.eigenvectors().col(2).normalized();
      CellRecord r{};
      r.type = CellType::parallel;
      const Vec3 a = A.transpose() * d;
      r.lam[0] = d[0], r.lam[1] = d[1], r.lam[2] = d[2];
      r.S[0] = a[0], r.S[1] = a[1], r.S[2] = a[2];
      r.c[0] = d.dot(b);
      r.c[1] = a.dot(d);
      return r;
    }
    return extraordinary(g, A, b, false);
  }

  const double rho = std::max({std::hypot(re[0], im[0]), std::abs(re[1]), std::abs(re[2])});
  const double tol = params.eps_distinct * std::max(rho, 1.0 / tauT);
  Mat3 S;
  CellRecord r{};
  if (all_real) {
    if (re[0] - re[1] <= tol || re[1] - re[2] <= tol) return extraordinary(g, A, b, false);
    for (int i = 0; i < 3; ++i) {
      Vec3 e = largest_cross(A - re[i] * Mat3::Identity());
      double n = e.norm();
      if (!(n > 0)) return extraordinary(g, A, b, false);
      S.col(i) = e / n;
      r.lam[i] = re[i];
    }
    r.type = CellType::normal_real;
  } else {
    const double alpha = re[0], beta = im[0];
    if (beta <= tol) return extraordinary(g, A, b, false);
    Eigen::Matrix<C, 3, 3> M = A.cast<C>();
    for (int i = 0; i < 3; ++i) M(i, i) -= C(alpha, beta);
    CVec w[3] = {complex_cross(M.row(0).transpose(), M.row(1).transpose()),
                 complex_cross(M.row(1).transpose(), M.row(2).transpose()),
                 complex_cross(M.row(2).transpose(), M.row(0).transpose())};
    int best = 0;
    for (int i = 1; i < 3; ++i)
      if (w[i].squaredNorm() > w[best].squaredNorm()) best = i;
    Vec3 b1 = w[best].real(), b2 = w[best].imag();
    // Turn the phase so that Re w and Im w are orthogonal: the best-conditioned basis.
    const double theta = 0.5 * std::atan2(-2.0 * b1.dot(b2), b1.squaredNorm() - b2.squaredNorm());
    const double cs = std::cos(theta), sn = std::sin(theta);
    Vec3 c1 = cs * b1 - sn * b2, c2 = sn * b1 + cs * b2;
    Vec3 e3 = largest_cross(A - re[2] * Mat3::Identity());
    if (!(c1.norm() > 0) || !(e3.norm() > 0)) return extraordinary(g, A, b, false);
    const double scale = 1.0 / c1.norm();
    S.col(0) = c1 * scale;
    S.col(1) = c2 * scale;
    S.col(2) = e3.normalized();
    r.lam[0] = alpha, r.lam[1] = beta, r.lam[2] = re[2];
    r.type = CellType::normal_complex;
  }
  // Scale the last column so that det S = 1 (§9.3.3); S^{-1} rows are then cross products.
  const double det = S.determinant();
  const double volume_ratio = std::abs(det) / (S.col(0).norm() * S.col(1).norm() * S.col(2).norm());
  if (!(volume_ratio * params.max_condition > 1.0)) return extraordinary(g, A, b, false);
  S.col(2) /= det;
  Mat3 Sinv;
  Sinv.row(0) = S.col(1).cross(S.col(2)).transpose();
  Sinv.row(1) = S.col(2).cross(S.col(0)).transpose();
  Sinv.row(2) = S.col(0).cross(S.col(1)).transpose();
  const Vec3 c = Sinv * b;
  store(S, r.S);
  store(Sinv, r.Sinv);
  r.c[0] = c[0], r.c[1] = c[1], r.c[2] = c[2];

  // Critical set in eigen coordinates: lambda_i z_i + c_i = 0 (the pair: M2 z + c = 0).
  Vec3 zc = Vec3::Zero();
  bool free_dim[3] = {false, false, false};
  double zmax[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    Vec3 z = Sinv * g.V[k];
    for (int i = 0; i < 3; ++i) zmax[i] = std::max(zmax[i], std::abs(z[i]));
  }
  bool none = false;
  auto real_coordinate = [&](int i, double lam) {
    const double tol_c = 1e-12 * g.v_max * Sinv.row(i).norm();
    if (std::abs(lam) * tauT <= 1e-12) {
      if (std::abs(c[i]) <= tol_c) free_dim[i] = true;
      else none = true;  // z_i' = c_i != 0: no rest point
    } else {
      zc[i] = -c[i] / lam;
      if (std::abs(zc[i]) > 2.0 * zmax[i] + 1e-300) none = true;  // far outside the cell
    }
  };
  if (r.type == CellType::normal_real) {
    for (int i = 0; i < 3; ++i) real_coordinate(i, r.lam[i]);
  } else {
    const double a = r.lam[0], bb = r.lam[1], n2 = a * a + bb * bb;
    // [[a, b], [-b, a]]^{-1} = [[a, -b], [b, a]] / (a^2 + b^2)
    zc[0] = -(a * c[0] - bb * c[1]) / n2;
    zc[1] = -(bb * c[0] + a * c[1]) / n2;
    real_coordinate(2, r.lam[2]);
  }
  r.critical_inside = !none && critical_set_inside(g, S, zc, free_dim);
  if (r.critical_inside) return extraordinary(g, A, b, true);
  return r;
}

}  // namespace fest::lemtrace
