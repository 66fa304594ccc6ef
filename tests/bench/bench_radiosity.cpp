// radiosity speed (docs/radiosity.md "Performance"): the Cornell box at about 2,000
// patches / 8,000 elements, hemicube 256, tol 1e-3 (target < 20 s on 2 cores), with
// plain progressive refinement (pr) in the same run as the anchor for the over-relaxed
// solvers' shot counts; the furnace cube with 6 x 32 x 32 patches (target < 10 s).
// One JSON line per case; peak memory is the process's ru_maxrss after the case.
//
//   bench_radiosity [--threads 2] [--patch-size 30] [--ff hybrid|hemicube] [--quick] [--no-furnace | --furnace-only]

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "core/threads.hpp"
#include "radiosity/cornell.hpp"
#include "radiosity/solver.hpp"

namespace {

using namespace fest::radiosity;
using Clock = std::chrono::steady_clock;

Scene furnace_scene() {
  Scene s;
  using V = Eigen::Vector3d;
  SceneObject o;
  o.name = "box";
  o.reflectance = Rgb::Constant(0.9);
  o.emission = Rgb::Constant(1);
  o.vertices = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 1), V(1, 1, 1), V(0, 1, 1)};
  o.faces = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
  s.objects.push_back(o);
  return s;
}

// CPU seconds of the process (all threads): on a shared, loaded machine the wall time
// counts other people's work too.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_utime.tv_usec * 1e-6 + u.ru_stime.tv_sec + u.ru_stime.tv_usec * 1e-6;
}

double peak_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

Engine g_engine = Engine::hybrid;

void run_case(const char* name, const Scene& scene, const MeshingOptions& mo, Solver solver, int res, int levels,
              int threads, long max_shots) {
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  Model m = build_model(scene, mo);
  FormFactorOptions fo;
  fo.engine = g_engine;
  fo.hemicube_res = res;
  fo.threads = threads;
  FormFactors ff(m, fo);
  SolveOptions so;
  so.solver = solver;
  so.tol = 1e-3;
  so.levels = levels;
  so.threads = threads;
  so.max_shots = max_shots;
  const SolveStats st = solve(m, ff, so);
  const double total = std::chrono::duration<double>(Clock::now() - t0).count();
  nlohmann::json j = {{"case", name},
                      {"solver", solver_name(solver)},
                      {"ff", g_engine == Engine::hybrid ? "hybrid" : "hemicube"},
                      {"patches", m.patches.size()},
                      {"elements", m.active_elements().size()},
                      {"hemicube_res", res},
                      {"levels", levels},
                      {"threads", threads},
                      {"shots", st.shots},
                      {"converged", st.converged},
                      {"seconds", total},
                      {"cpu_s", cpu_seconds() - c0},
                      {"visibility_s", st.visibility_seconds},
                      {"solve_s", st.solve_seconds},
                      {"subdivision_s", st.subdivision_seconds},
                      {"visibility_fraction", st.visibility_seconds / total},
                      {"peak_mb", peak_mb()}};
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int threads = 2;
  double patch = 30;
  bool quick = false, furnace = true, cornell_cases = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--patch-size") && i + 1 < argc) patch = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--ff") && i + 1 < argc) g_engine = std::strcmp(argv[++i], "hemicube") ? Engine::hybrid : Engine::hemicube;
    else if (!std::strcmp(argv[i], "--no-furnace")) furnace = false;
    else if (!std::strcmp(argv[i], "--furnace-only")) cornell_cases = false;
    else {
      // Unknown words stop here: the full run includes a furnace case of minutes.
      std::fprintf(stderr,
                   "usage: bench_radiosity [--threads N] [--patch-size MM] [--quick] [--ff hybrid|hemicube]\n"
                   "                       [--no-furnace | --furnace-only]\n"
                   "JSON lines: Cornell box (orpr, overshoot, pr, adaptive), then the 6x32x32 furnace.\n");
      return std::strcmp(argv[i], "--help") && std::strcmp(argv[i], "-h") ? 2 : 0;
    }
  }
  threads = fest::resolve_threads(threads);
  MeshingOptions cornell;
  cornell.patch_size = patch;
  cornell.element_size = patch / 2;
  const Scene box = cornell_box();
  const long cap = 1000000;
  if (cornell_cases) {
    run_case("cornell", box, cornell, Solver::orpr, 256, 0, threads, cap);
    run_case("cornell", box, cornell, Solver::overshoot, 256, 0, threads, cap);
    if (!quick) run_case("cornell", box, cornell, Solver::pr, 256, 0, threads, cap);  // the anchor
    run_case("cornell_adaptive", box, cornell, Solver::orpr, 256, 2, threads, cap);
  }
  if (!furnace) return 0;
  MeshingOptions f;
  f.patch_size = 1.0 / 32;
  f.element_size = 1.0 / 32;
  f.emission_is_radiance = false;
  run_case("furnace_rho0.9", furnace_scene(), f, Solver::orpr, 256, 0, threads, cap);
  if (!quick) run_case("furnace_rho0.9", furnace_scene(), f, Solver::pr, 256, 0, threads, cap);
  return 0;
}
