#pragma once
// The dense transforms of the `fdm` diagonalisation (docs/fluidsim.md §4 and §6): products
// Y(i, r) = sum_j P(i, j) Q(r, j) along one axis of a box array, with ONE summation order
// per element (j ascending, a multiply and an add per term, from 0) whatever the blocking.
// A general GEMM (Eigen's) sums in an order that depends on the shape of the call and on
// the processor's cache sizes, so splitting it over threads would change the results;
// with a fixed order every partition of the rows and columns gives the same bytes.

#include <cstddef>
#include <vector>

namespace fest::fluidsim {

// Element (i, j) of P is P[i * p_i + j * p_j]; element (r, j) of Q is
// Q[r * q_r + j * q_j]; Y(i, r) is written to Y[i + r * ldy]. Rows [0, rows), columns
// [0, cols), depth [0, depth). Single-threaded: callers split rows or columns.
void dense_product(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, const double* Q, std::ptrdiff_t q_r, std::ptrdiff_t q_j,
                   double* Y, std::ptrdiff_t ldy, int rows, int cols, int depth);

// The same in two steps, for a P shared by many calls (a transform matrix applied to every
// piece of a box): the rows of P packed once, then products with any Q.
std::vector<double> pack_rows(const double* P, std::ptrdiff_t p_i, std::ptrdiff_t p_j, int rows, int depth);
void dense_product_packed(const double* packed, int rows, const double* Q, std::ptrdiff_t q_r, std::ptrdiff_t q_j,
                          double* Y, std::ptrdiff_t ldy, int cols, int depth);

}  // namespace fest::fluidsim
