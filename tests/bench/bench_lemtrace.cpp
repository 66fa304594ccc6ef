// lemtrace against VTK's vtkStreamTracer (the anchor, docs/lemtrace.md §5), in the same process on
// the same grid and seeds: one JSON line per case.
//
//   build/bin/bench_lemtrace [--n 56] [--seeds 1000] [--threads 2] [--no-vtk]
//
// Grid: the Kuhn-split cube [-1, 1]^3 with n = 56 (1,053,696 tets, 185,193 points),
// field (-y, x, 0.05) (a helix, globally linear, so its paths are known: r = r0,
// angle = t, z = z0 + 0.05 t); seeds at z = -0.9, y = 0, x in [0.2, 0.8].
// Cases: preprocessing (mesh connectivity + every cell record: time and memory),
// LEM tracing (1 and N threads), VTK RK4 at 0.2 cell lengths (and RK2 with --rk2).
// Errors are the largest distance of any output point from the closed form at its
// time, and the largest radial error | r - r0 |.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamTracer.h>
#include <vtkUnstructuredGrid.h>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"
#include "lemtrace/vtk/tet_grid.hpp"

namespace {

using namespace fest::lemtrace;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// CPU time of the whole process (user + system): on a shared machine it says more about
// the cost of single-threaded work than the wall clock does.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double rss_mb(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(std::strlen(key))) / 1024.0;
  return 0;
}

struct Errors {
  double position = 0, radial = 0;
  void add(const Vec3& seed, const Vec3& x, double t) {
    const double r0 = std::hypot(seed[0], seed[1]);
    const Vec3 exact(r0 * std::cos(t), r0 * std::sin(t), seed[2] + 0.05 * t);
    position = std::max(position, (x - exact).norm());
    radial = std::max(radial, std::abs(std::hypot(x[0], x[1]) - r0));
  }
};


void vtk_case(vtkUnstructuredGrid* grid, const std::vector<Vec3>& seeds, bool rk2) {
  auto source = vtkSmartPointer<vtkPolyData>::New();
  auto sp = vtkSmartPointer<vtkPoints>::New();
  sp->SetDataTypeToDouble();
  for (const Vec3& s : seeds) sp->InsertNextPoint(s.data());
  source->SetPoints(sp);
  auto tracer = vtkSmartPointer<vtkStreamTracer>::New();
  tracer->SetInputData(grid);
  tracer->SetSourceData(source);
  tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  if (rk2) tracer->SetIntegratorTypeToRungeKutta2();
  else tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetIntegrationStepUnit(vtkStreamTracer::CELL_LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(0.2);
  tracer->SetMaximumPropagation(1000);
  tracer->SetMaximumNumberOfSteps(1000000);
  tracer->SetIntegrationDirectionToForward();
  tracer->SetComputeVorticity(false);
  const double rss0 = rss_mb("VmRSS:");
  const double cpu0 = cpu_seconds();
  auto t0 = Clock::now();
  tracer->Update();
  const double seconds = since(t0);
  const double cpu = cpu_seconds() - cpu0;
  vtkPolyData* out = tracer->GetOutput();
  vtkDataArray* time = out->GetPointData()->GetArray("IntegrationTime");
  vtkDataArray* seed_ids = out->GetCellData()->GetArray("SeedIds");
  Errors err;
  for (vtkIdType c = 0; c < out->GetNumberOfCells() && time && seed_ids; ++c) {
    const auto seed = static_cast<std::size_t>(seed_ids->GetTuple1(c));
    vtkIdType n;
    const vtkIdType* ids;
    out->GetCellPoints(c, n, ids);
    for (vtkIdType k = 0; k < n; ++k) {
      double p[3];
      out->GetPoint(ids[k], p);
      err.add(seeds[seed], Vec3(p[0], p[1], p[2]), time->GetTuple1(ids[k]));
    }
  }
  std::printf("{\"case\": \"vtk_stream_tracer_%s\", \"seeds\": %zu, \"step\": \"0.2 cell lengths\", \"seconds\": %.3f, "
              "\"cpu_seconds\": %.3f, \"points\": %lld, \"max_position_error\": %.3g, \"max_radial_error\": %.3g, \"rss_growth_mb\": %.1f}\n",
              rk2 ? "rk2" : "rk4", seeds.size(), seconds, cpu, static_cast<long long>(out->GetNumberOfPoints()),
              err.position, err.radial, rss_mb("VmRSS:") - rss0);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int n = 56, n_seeds = 1000, threads = 2;
  bool vtk = true, rk2 = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--n" && i + 1 < argc) n = std::atoi(argv[++i]);
    else if (a == "--seeds" && i + 1 < argc) n_seeds = std::atoi(argv[++i]);
    else if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (a == "--no-vtk") vtk = false;
    else if (a == "--rk2") rk2 = true;
    else {
      std::fprintf(stderr, "usage: bench_lemtrace [--n 56] [--seeds 1000] [--threads 2] [--no-vtk] [--rk2]\n");
      return 2;
    }
  }
  GenOptions go;
  go.kind = "helix";
  go.n = n;
  GeneratedGrid g = generate(go);
  std::vector<Vec3> seeds;
  for (int i = 0; i < n_seeds; ++i)
    seeds.emplace_back(0.2 + 0.6 * (n_seeds == 1 ? 0.0 : static_cast<double>(i) / (n_seeds - 1)), 0.0, -0.9);

  // Preprocessing: connectivity and all records (the generated arrays are input, as a
  // file read would be; their memory is not counted).
  const double rss_before = rss_mb("VmRSS:");
  const double cpu_before = cpu_seconds();
  auto t0 = Clock::now();
  TetMesh mesh = build_tet_mesh(std::move(g.points), std::move(g.vectors), g.cells, BuildOptions{}, nullptr);
  g.cells = RawCells{};
  const double build_s = since(t0);
  t0 = Clock::now();
  FieldGrid grid(std::move(mesh), ClassifyParams{}, Precompute::all, threads);
  const double records_s = since(t0);
  const double preprocess_cpu = cpu_seconds() - cpu_before;
  t0 = Clock::now();
  grid.locator();
  const double locator_s = since(t0);
  std::printf("{\"case\": \"lem_preprocess\", \"tets\": %zu, \"points\": %zu, \"threads\": %d, \"connectivity_s\": %.3f, "
              "\"records_s\": %.3f, \"connectivity_and_records_cpu_s\": %.3f, \"locator_s\": %.3f, \"grid_bytes_per_tet\": %.1f, \"rss_growth_mb\": %.1f, "
              "\"peak_rss_mb\": %.1f}\n",
              grid.mesh().tets.size(), grid.mesh().points.size(), threads, build_s, records_s, preprocess_cpu, locator_s,
              static_cast<double>(grid.bytes()) / static_cast<double>(grid.mesh().tets.size()),
              rss_mb("VmRSS:") - rss_before, rss_mb("VmHWM:"));
  std::fflush(stdout);

  for (int th : {1, threads}) {
    TraceOptions o;
    const double cpu0 = cpu_seconds();
    t0 = Clock::now();
    const std::vector<double> t_start(seeds.size(), 0.0);
    const std::vector<Polyline> lines = trace_all(grid, seeds, t_start, o, th);
    const double seconds = since(t0);
    const double cpu = cpu_seconds() - cpu0;
    Errors err;
    long long points = 0, cells = 0, evals = 0, ended = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      points += static_cast<long long>(lines[i].x.size());
      cells += lines[i].cells;
      evals += lines[i].evaluations;
      ended += lines[i].reason == Reason::out_of_domain;
      for (std::size_t k = 0; k < lines[i].x.size(); ++k) err.add(seeds[i], lines[i].x[k], lines[i].t[k]);
    }
    std::printf("{\"case\": \"lem_trace\", \"seeds\": %zu, \"threads\": %d, \"seconds\": %.3f, \"cpu_seconds\": %.3f, \"cells_crossed\": %lld, "
                "\"crossings_per_s_per_thread\": %.0f, \"evaluations_per_cell\": %.2f, \"points\": %lld, "
                "\"lines_out_of_domain\": %lld, \"max_position_error\": %.3g, \"max_radial_error\": %.3g}\n",
                seeds.size(), th, seconds, cpu, cells, static_cast<double>(cells) / seconds / th,
                static_cast<double>(evals) / static_cast<double>(cells), points, ended, err.position, err.radial);
    std::fflush(stdout);
    if (th == threads) break;
  }
  if (!vtk) {
    std::printf("{\"case\": \"vtk_stream_tracer_rk4\", \"note\": \"skipped (--no-vtk)\"}\n");
    return 0;
  }
  vtkSmartPointer<vtkUnstructuredGrid> vgrid = tet_mesh_to_vtk(grid.mesh());
  vtk_case(vgrid, seeds, false);
  if (rk2) vtk_case(vgrid, seeds, true);
  return 0;
}
