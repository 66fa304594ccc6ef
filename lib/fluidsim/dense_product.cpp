#include "fluidsim/dense_product.hpp"

#include <cstring>
#include <vector>

namespace fest::fluidsim {

namespace {

// Two lanes with the x86-64 baseline (SSE2); other targets lower the same code generically.
using Double2 = double __attribute__((vector_size(16)));

inline Double2 load2(const double* p) noexcept {
  Double2 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline void store2(double* p, Double2 v) noexcept { std::memcpy(p, &v, sizeof v); }

constexpr int kRows = 8;  // rows per register block: one cache line of each P column

}  // namespace

void dense_product(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, const double* Q, std::ptrdiff_t q_r, std::ptrdiff_t q_j,
                   double* Y, std::ptrdiff_t ldy, int rows, int cols, int depth) {
  // Each block of 8 rows of P is packed contiguously first (zero rows pad the last
  // block): a column of P a whole plane apart (the z transform) would otherwise map every
  // depth step onto the same few cache sets. The padded lanes are computed and dropped;
  // lanes never mix, so a row's sum is the same in every block position.
  std::vector<double> pack(static_cast<std::size_t>(kRows) * depth);
  for (int i0 = 0; i0 < rows; i0 += kRows) {
    const int n = rows - i0 < kRows ? rows - i0 : kRows;
    for (int j = 0; j < depth; ++j) {
      const double* src = P + i0 * p_i + j * p_j;
      double* dst = pack.data() + static_cast<std::size_t>(j) * kRows;
      for (int i = 0; i < n; ++i) dst[i] = src[i * p_i];
      for (int i = n; i < kRows; ++i) dst[i] = 0.0;
    }
    auto store = [&](double* y, Double2 a0, Double2 a1, Double2 a2, Double2 a3) {
      if (n == kRows) {
        store2(y, a0);
        store2(y + 2, a1);
        store2(y + 4, a2);
        store2(y + 6, a3);
        return;
      }
      const double lanes[kRows] = {a0[0], a0[1], a1[0], a1[1], a2[0], a2[1], a3[0], a3[1]};
      for (int i = 0; i < n; ++i) y[i] = lanes[i];
    };
    int r = 0;
    for (; r + 2 <= cols; r += 2) {  // two columns at a time: 8 accumulators
      const double* q0 = Q + r * q_r;
      const double* q1 = q0 + q_r;
      Double2 a0{0, 0}, a1{0, 0}, a2{0, 0}, a3{0, 0}, b0{0, 0}, b1{0, 0}, b2{0, 0}, b3{0, 0};
      const double* p = pack.data();
      for (int j = 0; j < depth; ++j, p += kRows) {
        const Double2 p0 = load2(p), p1 = load2(p + 2), p2 = load2(p + 4), p3 = load2(p + 6);
        const double x = q0[j * q_j], y = q1[j * q_j];
        const Double2 s = {x, x}, t = {y, y};
        a0 += p0 * s;
        a1 += p1 * s;
        a2 += p2 * s;
        a3 += p3 * s;
        b0 += p0 * t;
        b1 += p1 * t;
        b2 += p2 * t;
        b3 += p3 * t;
      }
      store(Y + i0 + r * ldy, a0, a1, a2, a3);
      store(Y + i0 + (r + 1) * ldy, b0, b1, b2, b3);
    }
    if (r < cols) {  // the odd last column: the same sums, one column
      const double* q0 = Q + r * q_r;
      Double2 a0{0, 0}, a1{0, 0}, a2{0, 0}, a3{0, 0};
      const double* p = pack.data();
      for (int j = 0; j < depth; ++j, p += kRows) {
        const double x = q0[j * q_j];
        const Double2 s = {x, x};
        a0 += load2(p) * s;
        a1 += load2(p + 2) * s;
        a2 += load2(p + 4) * s;
        a3 += load2(p + 6) * s;
      }
      store(Y + i0 + r * ldy, a0, a1, a2, a3);
    }
  }
}

}  // namespace fest::fluidsim
