// softobj benchmarks (docs/softobj.md §6): shrink-wrap against the marching-cubes anchor
// (fest's exact marching cubes on the same field, vertices projected) at equal maximum deviation --
// the largest distance from the surface over a lattice of 12 points in every triangle
// (max_sampled_deviation, the same function for both meshes) -- found by bisecting the
// grid spacing; and the time of one default tongue frame. One JSON line per case. Two
// criteria: the seed's chord rule (alpha, L_max) alone ("chord"), and the deviation-driven
// refinement ("deviation", max_deviation = tol, alpha only a loose bound).
// Usage: bench_softobj [case-name-prefix]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "marching_cubes.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/shrinkwrap.hpp"
#include "softobj/tongue.hpp"

using namespace fest::softobj;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

const char* g_filter = nullptr;

void compare(const char* name, const Skeleton& s, double rho, double alpha, double lmax_factor, double tol = 0) {
  if (g_filter && std::strncmp(name, g_filter, std::strlen(g_filter)) != 0) return;
  const Field f(compile_terms(s));
  ShrinkwrapOptions o;
  o.iso = 1 / rho;
  o.alpha_deg = alpha;
  o.lmax = lmax_factor * rho;
  o.max_deviation = tol;
  auto t0 = std::chrono::steady_clock::now();
  const fest::TriMesh sw = shrinkwrap(f, o);
  const double t_sw = seconds_since(t0);
  const double dev = max_sampled_deviation(f, sw, o.iso);
  const double cdev = max_centroid_deviation(f, sw, o.iso);
  const MeshMeasures mm = measure(sw);
  // Bisect h (deviation grows with h) for the coarsest grid within the same deviation.
  double lo = rho / 50, hi = rho;
  std::size_t mc_tris = 0;
  double mc_dev = 0, t_mc = 0;
  for (int it = 0; it < 12; ++it) {
    const double h = std::sqrt(lo * hi);
    t0 = std::chrono::steady_clock::now();
    const fest::TriMesh mc = fest::softobj_tool::marching_cubes(f, o.iso, rho, h, 50000000);
    const double t = seconds_since(t0);
    const double d = max_sampled_deviation(f, mc, o.iso);
    if (d <= dev) lo = h, mc_tris = mc.n_faces(), mc_dev = d, t_mc = t;
    else hi = h;
  }
  std::printf("{\"case\": \"%s\", \"criterion\": \"%s\", \"alpha_deg\": %g, \"lmax_over_rho\": %g, "
              "\"tol\": %g, \"shrinkwrap_triangles\": %zu, \"max_deviation\": %.4g, \"centroid_deviation\": %.4g, "
              "\"volume\": %.2f, \"euler\": %d, \"closed\": %d, \"shrinkwrap_s\": %.3f, \"mc_grid\": %.4g, "
              "\"mc_triangles\": %zu, \"mc_deviation\": %.4g, \"mc_s\": %.3f, \"ratio\": %.2f}\n",
              name, tol > 0 ? "deviation" : "chord", alpha, lmax_factor, tol, sw.n_faces(), dev, cdev, mm.volume,
              mm.euler_characteristic, mm.closed ? 1 : 0, t_sw, lo, mc_tris, mc_dev, t_mc,
              static_cast<double>(mc_tris) / static_cast<double>(sw.n_faces()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) g_filter = argv[1];
  Skeleton square;
  square.vertices = {{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  Skeleton capsule;
  capsule.vertices = {{0, 0, 0}, {20, 0, 0}};
  capsule.segments = {{0, 1}};
  const Skeleton tongue = tongue_skeleton(neutral_tongue(), TongueLayout::default10, 6);
  for (double a : {15.0, 10.0}) {  // the seed's chord rule alone (before)
    compare("square_slab", square, 5, a, 3);
    compare("tongue", tongue, 6, a, 1);
    compare("capsule", capsule, 5, a, 3);
  }
  for (double tol : {0.08, 0.04}) {  // deviation-driven refinement (after)
    compare("square_slab", square, 5, 40, 3, tol);
    compare("capsule", capsule, 5, 40, 3, tol);
  }
  for (double tol : {0.15, 0.1}) compare("tongue", tongue, 6, 40, 3, tol);
  if (g_filter) return 0;
  // One default tongue frame, single-threaded (target < 50 ms), and the sphere at 5 deg.
  const Field tf(compile_terms(tongue));
  ShrinkwrapOptions o;
  o.iso = 1.0 / 6;
  const int reps = 5;
  auto t0 = std::chrono::steady_clock::now();
  std::size_t tris = 0;
  for (int i = 0; i < reps; ++i) tris = shrinkwrap(tf, o).n_faces();
  std::printf("{\"case\": \"tongue_frame\", \"triangles\": %zu, \"ms\": %.1f, \"target_ms\": 50}\n", tris,
              1000 * seconds_since(t0) / reps);
  Skeleton point;
  point.vertices = {{0, 0, 0}};
  point.points = {0};
  const Field pf(compile_terms(point));
  o.iso = 0.1;
  o.alpha_deg = 5;
  t0 = std::chrono::steady_clock::now();
  tris = shrinkwrap(pf, o).n_faces();
  std::printf("{\"case\": \"sphere_alpha5\", \"triangles\": %zu, \"s\": %.3f, \"target_s\": 0.2}\n", tris,
              seconds_since(t0));
  return 0;
}
