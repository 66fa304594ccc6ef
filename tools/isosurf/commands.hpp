#pragma once
// isosurf's command library (fest_isosurf_app): typed options and one function per
// subcommand. main.cpp only fills these from the flags.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "formats/volume_source/volume_source.hpp"
#include "isosurface/adaptive.hpp"

namespace fest::isosurf_tool {

struct ExactOptions {
  std::string input = "-";
  std::string output = "-";
  std::string to;                     // ply | plya | obj | off | stl | drc ("" = from -o, else ply)
  std::optional<double> iso;
  std::vector<long long> labels;      // surface of the union of these labels (iso 0.5 of the indicator); empty = --iso
  std::string field;                  // VTI / frame stream
  formats::VectorComponent component = formats::VectorComponent::mag;
  long frame = -1;
  std::optional<formats::RawLayout> raw;  // --raw: the input is a headerless volume
  bool cap = false;                   // pad by one layer of cap_value
  std::optional<double> cap_value;    // default: min(f) - 1
  isosurface::FaceRule face_rule = isosurface::FaceRule::decider;
  isosurface::Triangulation tri = isosurface::Triangulation::minarea;
  std::size_t keep_components = 0;    // --component-filter: 0 = all, else the N largest
  bool index_space = false;
  bool nan_outside = false;
  std::optional<std::array<long long, 6>> roi;  // i0,i1,j0,j1,k0,k1: inclusive sample ranges
  bool normals = false;               // per-vertex normals -grad f / |grad f| in the output
  int smooth = 0;                     // Taubin lambda|mu iterations
  bool no_octree = false;             // brute-force scan (same output; for comparisons)
  int qbits = 14;                     // drc position quantization (0 = lossless)
  int threads = 0;
  bool progress = false;  // --progress: read, extract, write (progressive: meshes)
  std::string report;
  bool quiet = false;
};

struct AdaptiveArgs {
  std::optional<std::array<double, 3>> focus;  // world units
  double focus_radius = 0;            // r0; 0 = diagonal / 32
  double max_error = 0;               // eps0 (data units); +inf = distance rule only
  double error_growth = 1;
  int max_level = -1;
  isosurface::EdgeRule edge_rule = isosurface::EdgeRule::transitions;  // closure (docs/isosurf.md 5.2)
};

struct ProgressiveArgs {
  std::vector<double> errors;  // E0, E1, ..., 0 descending
  std::string focus_path;  // CSV rows x,y,z: one adaptive mesh per focus position
};

struct StatsOptions {
  std::string input = "-";
  std::string report;                 // also write the JSON here
};

int run_exact(const ExactOptions& options);
int run_adaptive(const ExactOptions& options, const AdaptiveArgs& adaptive);
int run_stats(const StatsOptions& options);
int run_progressive(const ExactOptions& options, const AdaptiveArgs& adaptive, const ProgressiveArgs& progressive);

}  // namespace fest::isosurf_tool
