#pragma once
// Semi-Lagrangian advection (docs/fluidsim.md §2, step 2): every node traces back along
// the frozen velocity field with classical RK4 (substeps optional) and takes the
// trilinear sample of each field there. Nodes are independent: a parallel loop with
// dynamic chunks, no synchronisation.

#include <vector>

#include "fluidsim/grid.hpp"

namespace fest::fluidsim {

// The departure point of node (i,j,k) in index coordinates (one node; advect() traces
// every node without repacking the velocity each time).
std::array<double, 3> trace_back(const Layout& layout, const Velocity& vel, int i, int j, int k, double dt,
                                 int substeps);

// out[f] = in[f] sampled at the departure points through `vel`; in and out must differ.
void advect(const Layout& layout, const Velocity& vel, double dt, int substeps, const std::vector<const Field*>& in,
            const std::vector<Field*>& out);

}  // namespace fest::fluidsim
