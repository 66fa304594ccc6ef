// Simulator::step, the projector and the diffusers keep their work buffers from one call
// to the next (docs/fluidsim.md §6). Whatever a step leaves in them must not reach the
// next: a simulator that has stepped one state and then steps another gives the bytes a
// fresh simulator gives for the second, with diffusion, scalars, both step orders and
// mass correction, on a grid above the threshold where the team is used.
#include <gtest/gtest.h>

#include "fluidsim/scene.hpp"
#include "fluidsim/simulator.hpp"

namespace {

using namespace fest::fluidsim;

Scene plume_scene() {
  Scene sc;
  sc.dims = {34, 33, 32};  // 35,904 nodes: above kParallelNodes
  sc.viscosity = 2e-3;
  Source src;
  src.shape = Source::Shape::sphere;
  src.centre = {17, 16, 6};
  src.radius = 4;
  src.rate = 10.0;
  src.jet = true;
  src.velocity = {0, 0, 0.5};
  add_plume(sc, src);
  sc.scalars[0].kappa = 1e-3;
  sc.scalars[0].alpha = 0.1;
  return sc;
}

bool same_bytes(const State& a, const State& b) {
  for (int c = 0; c < 3; ++c)
    if (a.u[c] != b.u[c]) return false;
  return a.s == b.s && a.t == b.t && a.step == b.step;
}

}  // namespace

TEST(FluidsimBuffers, ReusedBuffersDoNotCarryOneStateIntoAnother) {
  ASSERT_GE(plume_scene().layout().count(), kParallelNodes);
  for (bool stam03 : {false, true})
    for (bool mass : {false, true})
      for (PoissonSolver solver : {PoissonSolver::fdm, PoissonSolver::fft}) {
        SCOPED_TRACE(testing::Message() << "stam03 " << stam03 << " mass " << mass << " solver " << int(solver));
        SimOptions so;
        so.stam03 = stam03;
        so.mass_correct = mass;
        so.projection.solver = solver;
        const Scene sc = plume_scene();
        const Simulator used(sc, so);
        State a = used.initial_state();
        for (int k = 0; k < 3; ++k) used.step(a, 0.05);  // the buffers now hold a's fields
        // A different state: b is a advanced by a fresh simulator, then scaled.
        State b = a;
        for (int c = 0; c < 3; ++c)
          for (double& v : b.u[c]) v *= -0.5;
        for (double& v : b.s[0]) v = 0.25 * v + 0.01;
        State from_used = b, from_fresh = b;
        used.step(from_used, 0.05);
        used.step(from_used, 0.05);
        const Simulator fresh(sc, so);
        fresh.step(from_fresh, 0.05);
        fresh.step(from_fresh, 0.05);
        EXPECT_TRUE(same_bytes(from_used, from_fresh));
        // And the blend into a kept State equals the blend into a fresh one.
        State kept = a;
        blend(a, from_used, 0.3, kept);
        blend(from_fresh, a, 0.6, kept);
        EXPECT_TRUE(same_bytes(kept, blend(from_fresh, a, 0.6)));
      }
}
