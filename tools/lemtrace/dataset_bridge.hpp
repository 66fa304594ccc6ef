#pragma once
// lemtrace's dataset side: datasets read by formats/ turned into the plain arrays
// lib/lemtrace takes, and its results turned back into datasets for formats/ to write.

#include <string>
#include <vector>

#include "core/dataset.hpp"
#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"

namespace fest::lemtrace_tool {

using namespace fest::lemtrace;

struct LoadedGrid {
  std::vector<Vec3> points;
  std::vector<Vec3> vectors;
  RawCells cells;
  std::string vector_name;
  bool linear = false;     // a gen grid with a globally linear field (field data)
  LinearField field;
  std::string kind;        // gen kind, or empty
};

// Picks the vector array (lemtrace(1): --vectors NAME, else the active vectors, else the only
// 3-component point array) and converts unstructured, image and structured grids.
// Throws bad_input naming what is missing, ambiguous or non-finite.
LoadedGrid grid_from_dataset(const Dataset& dataset, const std::string& vectors_name);

// A gen grid as an unstructured grid with point vectors "velocity" and field data
// LemtraceKind / LemtraceA / LemtraceB.
Dataset dataset_from_generated(const GeneratedGrid& grid, const std::string& kind);

struct LineSet {
  const std::vector<Polyline>* lines;
  const std::vector<double>* seed_ids;
  std::string options;     // recorded in field data
};

Dataset polylines_to_dataset(const FieldGrid& grid, const LineSet& set);

// The tetrahedral mesh as one VTK_TETRA per tet, point vectors "velocity" (what
// lib/lemtrace/vtk/tet_grid.hpp hands to VTK in the benchmarks).
Dataset tet_mesh_dataset(const TetMesh& mesh);

// The traced grid with cell arrays LemType, Eigenvalues, CriticalPointInside.
Dataset classified_dataset(const FieldGrid& grid, const std::vector<CellRecord>& records);

// Points of a point set (.vtp/.vtk) used as seeds.
std::vector<Vec3> points_of(const Dataset& dataset);

// Velocity of the piecewise-linear field at x inside `cell`.
Vec3 velocity_at(const FieldGrid& grid, int32_t cell, const Vec3& x);

}  // namespace fest::lemtrace_tool
