#pragma once
// Generalised quadric error metric (Garland & Heckbert 1998, "Simplifying surfaces with
// color and texture using quadric error metrics", section 4): a vertex is a point
// v = (x, y, z, a_1 .. a_m) in R^n, n = 3 + m (m attribute values: normal, colour,
// texture coordinates, each scaled by a weight); a triangle defines the squared distance
// of v from the triangle's plane in R^n,
//     Q(v) = v^T A v + 2 b^T v + c,
// with A = I - e1 e1^T - e2 e2^T, b = (p.e1) e1 + (p.e2) e2 - p,
// c = p.p - (p.e1)^2 - (p.e2)^2 (their equations 2-4; e1, e2 an orthonormal frame of the
// triangle in R^n). For m = 0 this is the plane quadric of Garland & Heckbert 1997.
// See docs/decimate.md section 2.1.

#include <array>
#include <cstddef>

namespace fest::decimate {

// Largest dimension n handled: position (3) + normal (3) + colour (3) + texcoord (2).
inline constexpr int max_dimension = 11;

// A quadric in R^n stored as the upper triangle of A (row-major), b and c, plus the
// total weight (area) that went into it.
class Quadric {
 public:
  Quadric() = default;
  explicit Quadric(int n) : n_(n) {
    a_.fill(0.0);
    b_.fill(0.0);
  }

  int dimension() const noexcept { return n_; }
  double weight() const noexcept { return w_; }
  void set_weight(double w) noexcept { w_ = w; }

  // Area-weighted quadric of triangle (p, q, r) in R^n (GH98 eq. 2-4).
  static Quadric triangle(const double* p, const double* q, const double* r, int n, double weight);
  // A plane through `point` with unit normal `normal` acting on the position part only:
  // the boundary and feature constraint planes of GH97 section 6.
  static Quadric position_plane(const double point[3], const double normal[3], int n, double weight);

  Quadric& operator+=(const Quadric& o);

  // Packed form for per-vertex storage (n(n+1)/2 + n + 2 doubles: A, b, c, weight), so a
  // mesh of positions only costs 11 doubles per vertex, not the fixed maximum.
  static constexpr std::size_t packed_size(int n) { return static_cast<std::size_t>(n * (n + 1) / 2 + n + 2); }
  static Quadric unpack(const double* packed, int n);
  void add_to_packed(double* packed) const;
  // Evaluation and minimisation straight on the packed form (the collapse loop's path:
  // no copies of the fixed-size arrays).
  static double evaluate_packed(const double* packed, int n, const double* v);
  static bool minimise_packed(const double* packed, int n, double* v);
  double evaluate(const double* v) const;
  // The minimiser of Q (solves A v = -b); false when A is singular or badly conditioned.
  bool minimise(double* v) const;

 private:
  double a(int i, int j) const { return i <= j ? a_[index(i, j)] : a_[index(j, i)]; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i * n_ - i * (i - 1) / 2 + (j - i)); }
  int n_ = 0;
  // Fixed storage: quadrics are copied and summed in the inner loop, never allocated.
  std::array<double, max_dimension*(max_dimension + 1) / 2> a_{};
  std::array<double, max_dimension> b_{};
  double c_ = 0;
  double w_ = 0;
};

}  // namespace fest::decimate
