#pragma once
// The discrete operators of the projection (docs/fluidsim.md §4): central divergence D
// and gradient G with the mirror rules of the grid, and the weighted inner product in
// which the projection is orthogonal.

#include "fluidsim/grid.hpp"

namespace fest::fluidsim {

// out = D u, at every stored node (wall nodes included); u's normal components are odd.
void divergence(const Layout& layout, const Velocity& u, Field& out);

// max |D u| without storing D u (the projection's after-check); a non-finite value if
// D u has one.
double max_abs_divergence(const Layout& layout, const Velocity& u);

// u -= G q for an even q.
void subtract_gradient(const Layout& layout, const Field& q, Velocity& u);

// max |f|.
double max_abs(const Field& f) noexcept;

// Trapezoid weights of a stored node: 1/2 per closed axis on which it is a wall node.
double node_weight(const Layout& layout, int i, int j, int k) noexcept;

// <a, b>_W summed over the active components.
double weighted_dot(const Layout& layout, const Velocity& a, const Velocity& b);

// Kinetic energy 1/2 <u, u>_W h^d.
double kinetic_energy(const Layout& layout, const Velocity& u);

// Weighted sum (trapezoid) of a scalar times h^d: the discrete mass.
double weighted_sum(const Layout& layout, const Field& s);

}  // namespace fest::fluidsim
