// The point location of Table 9.4's integrators against VTK's standard cell searches
// (docs/lemtrace.md §5). The chapter's integration loop (§9.2.1) finds "the cell
// containing the new position" after every step -- "in irregular grids a time consuming
// cell search is needed for every evaluation" -- and the LEM needs none after the seed
// (§9.2.3). bench_lemtrace_steps' `euler_cell_search` uses lemtrace's bin-grid
// CellLocator::locate for that search; this bench shows what such a search costs next to
// the searches a VTK user would call, on the same grid and the same query points, so the
// baseline is neither a strawman nor unusually lean.
//
//   build/bin/bench_lemtrace_locate [--repeat 5]
//
// Grid and points: `lemtrace gen sphere-rotation --n 20` and the positions of the
// Table 9.4 Euler lines (50 seeds, one revolution, the LEM's cell count as step count),
// i.e. exactly the points euler_cell_search locates. One JSON line per search: ns per
// query (best of --repeat) and how many queries found a cell.
//   fest_bin_grid        CellLocator::locate (uniform bins over the cells' boxes)
//   fest_walk            CellLocator::walk from the previous point's cell (the baseline
//                        `euler` of bench_lemtrace_steps; not a search, a neighbour walk)
//   vtk_static_locator   vtkStaticCellLocator::FindCell (VTK's fastest general locator)
//   vtk_cell_locator     vtkCellLocator::FindCell (VTK's classic octree-like bins)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

#include <vtkCellLocator.h>
#include <vtkGenericCell.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"
#include "lemtrace/vtk/tet_grid.hpp"
#include "lemtrace_table94.hpp"

namespace {

using namespace fest::lemtrace;

double best_ns(int repeat, std::size_t queries, const std::function<long()>& run, long& found) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    found = run();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
  }
  return 1e9 * best / static_cast<double>(queries);
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));

  TetMesh mesh = bench::table94_mesh();
  vtkSmartPointer<vtkUnstructuredGrid> ugrid = tet_mesh_to_vtk(mesh);
  const FieldGrid grid(std::move(mesh), ClassifyParams{}, Precompute::all, 1);
  const CellLocator& locator = grid.locator();

  // The query points: every position of the Table 9.4 Euler lines (as in
  // bench_lemtrace_steps: h = T / S with S the LEM's cell count on that line).
  std::vector<Vec3> points;
  for (const Vec3& seed : bench::table94_seeds()) {
    const Polyline ref = trace(grid, seed, 0.0, bench::table94_lem());
    const Polyline line = trace(grid, seed, 0.0, bench::equal_step_options(Method::euler, ref));
    points.insert(points.end(), line.x.begin(), line.x.end());
  }

  auto report = [&](const char* name, double ns, long found) {
    std::printf("{\"bench\":\"lemtrace_locate\",\"search\":\"%s\",\"queries\":%zu,\"found\":%ld,\"ns_per_query\":%.1f}\n",
                name, points.size(), found, ns);
  };
  long found = 0;
  double ns = best_ns(repeat, points.size(), [&] {
    long f = 0;
    for (const Vec3& x : points) f += locator.locate(x) >= 0;
    return f;
  }, found);
  report("fest_bin_grid", ns, found);

  ns = best_ns(repeat, points.size(), [&] {
    long f = 0;
    int32_t cell = locator.locate(points.front());
    for (const Vec3& x : points) {
      const int32_t c = locator.walk(cell, x, nullptr);
      if (c >= 0) cell = c, ++f;
    }
    return f;
  }, found);
  report("fest_walk", ns, found);

  auto vtk_search = [&](auto locator_ptr, const char* name) {
    locator_ptr->SetDataSet(ugrid);
    locator_ptr->BuildLocator();
    auto cell = vtkSmartPointer<vtkGenericCell>::New();
    double pcoords[3], weights[8];
    const double tol2 = 1e-24;
    ns = best_ns(repeat, points.size(), [&] {
      long f = 0;
      for (const Vec3& x : points) {
        double p[3] = {x[0], x[1], x[2]};
        f += locator_ptr->FindCell(p, tol2, cell, pcoords, weights) >= 0;
      }
      return f;
    }, found);
    report(name, ns, found);
  };
  vtk_search(vtkSmartPointer<vtkStaticCellLocator>::New(), "vtk_static_locator");
  vtk_search(vtkSmartPointer<vtkCellLocator>::New(), "vtk_cell_locator");
  return 0;
}
