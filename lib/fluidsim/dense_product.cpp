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

// One block of W packed rows (pack[j * W + i]) against every column: Y(i, r) for i < n.
// Two columns at a time (2 W / 2 accumulators), the odd last column alone; each lane sums
// its own row, j ascending from 0.
template <int W>
void block(const double* pack, int n, const double* Q, std::ptrdiff_t q_r, std::ptrdiff_t q_j, double* Y,
           std::ptrdiff_t ldy, int cols, int depth) {
  constexpr int V = W / 2;
  auto store = [n](double* y, const Double2* acc) {
    for (int i = 0; i < n; ++i) y[i] = acc[i / 2][i % 2];
  };
  int r = 0;
  for (; r + 2 <= cols; r += 2) {
    const double* q0 = Q + r * q_r;
    const double* q1 = q0 + q_r;
    Double2 a[V], b[V];
    for (int v = 0; v < V; ++v) a[v] = b[v] = Double2{0.0, 0.0};
    const double* p = pack;
    for (int j = 0; j < depth; ++j, p += W) {
      const double x = q0[j * q_j], y = q1[j * q_j];
      const Double2 s = {x, x}, t = {y, y};
      for (int v = 0; v < V; ++v) {
        const Double2 pv = load2(p + 2 * v);
        a[v] += pv * s;
        b[v] += pv * t;
      }
    }
    store(Y + r * ldy, a);
    store(Y + (r + 1) * ldy, b);
  }
  if (r < cols) {
    const double* q0 = Q + r * q_r;
    Double2 a[V];
    for (int v = 0; v < V; ++v) a[v] = Double2{0.0, 0.0};
    const double* p = pack;
    for (int j = 0; j < depth; ++j, p += W) {
      const double x = q0[j * q_j];
      const Double2 s = {x, x};
      for (int v = 0; v < V; ++v) a[v] += load2(p + 2 * v) * s;
    }
    store(Y + r * ldy, a);
  }
}

// Copies rows [i0, i0 + n) of P into pack (W values per depth step), zero rows after n.
void pack_block(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, int i0, int n, int W, int depth,
                double* pack) {
  for (int j = 0; j < depth; ++j) {
    const double* src = P + i0 * p_i + j * p_j;
    double* dst = pack + static_cast<std::size_t>(j) * W;
    for (int i = 0; i < n; ++i) dst[i] = src[i * p_i];
    for (int i = n; i < W; ++i) dst[i] = 0.0;
  }
}

}  // namespace

// Rows go in blocks of 8 (one cache line of a P column), packed contiguously: a column of
// P a whole plane apart (the z transform) would otherwise map every depth step onto the
// same few cache sets. The last rows go in blocks of 2, the last odd row padded with a
// zero row whose lane is dropped. Lanes never mix, so a row's sum is the same in every
// block and piece.
std::vector<double> pack_rows(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, int rows, int depth) {
  const int full = rows / 8 * 8;
  std::vector<double> packed(static_cast<std::size_t>(full + (rows - full + 1) / 2 * 2) * depth);
  double* out = packed.data();
  int i0 = 0;
  for (; i0 < full; i0 += 8, out += static_cast<std::size_t>(8) * depth) pack_block(P, p_i, p_j, i0, 8, 8, depth, out);
  for (; i0 < rows; i0 += 2, out += static_cast<std::size_t>(2) * depth)
    pack_block(P, p_i, p_j, i0, rows - i0 < 2 ? rows - i0 : 2, 2, depth, out);
  return packed;
}

void dense_product_packed(const double* packed, int rows, const double* Q, std::ptrdiff_t q_r, std::ptrdiff_t q_j,
                          double* Y, std::ptrdiff_t ldy, int cols, int depth) {
  int i0 = 0;
  for (; i0 + 8 <= rows; i0 += 8, packed += static_cast<std::size_t>(8) * depth)
    block<8>(packed, 8, Q, q_r, q_j, Y + i0, ldy, cols, depth);
  for (; i0 < rows; i0 += 2, packed += static_cast<std::size_t>(2) * depth)
    block<2>(packed, rows - i0 < 2 ? rows - i0 : 2, Q, q_r, q_j, Y + i0, ldy, cols, depth);
}

void dense_product(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, const double* Q, std::ptrdiff_t q_r,
                   std::ptrdiff_t q_j, double* Y, std::ptrdiff_t ldy, int rows, int cols, int depth) {
  const std::vector<double> packed = pack_rows(P, p_i, p_j, rows, depth);
  dense_product_packed(packed.data(), rows, Q, q_r, q_j, Y, ldy, cols, depth);
}

}  // namespace fest::fluidsim
