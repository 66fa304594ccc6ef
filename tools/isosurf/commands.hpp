#pragma once
// isosurf's command library (fest_isosurf_app): typed options and one function per
// subcommand. main.cpp only fills these from the flags.

#include <optional>
#include <string>

namespace fest::isosurf {

struct ExactOptions {
  std::string input = "-";
  std::string output = "-";
  std::string to;                     // ply | plya | obj | off | stl | drc ("" = from -o, else ply)
  std::optional<double> iso;
  std::string labels;                 // "3,7,8": surface of the union of these labels (iso 0.5 of the indicator)
  std::string field;                  // VTI / frame stream
  std::string component = "mag";
  long frame = -1;
  bool cap = false;                   // pad by one layer of cap_value
  std::optional<double> cap_value;    // default: min(f) - 1
  std::string face_rule = "decider";  // decider | separate
  std::string tri = "minarea";        // minarea | fan | centroid
  std::string component_filter = "all";  // all | largest | N
  bool index_space = false;
  bool nan_outside = false;
  std::string roi;                    // "i0,i1,j0,j1,k0,k1": inclusive sample ranges ("" = all)
  bool normals = false;               // per-vertex normals -grad f / |grad f| in the output
  int smooth = 0;                     // Taubin lambda|mu iterations
  bool no_octree = false;             // brute-force scan (same output; for comparisons)
  int qbits = 14;                     // drc position quantization (0 = lossless)
  int threads = 0;
  std::string report;
  bool quiet = false;
};

struct AdaptiveArgs {
  std::string focus;                  // "X,Y,Z" world units ("" = none)
  double focus_radius = 0;            // r0; 0 = diagonal / 32
  std::string max_error = "0";        // eps0 (data units) or "inf"
  double error_growth = 1;
  int max_level = -1;
  std::string edge_rule = "transitions";  // closure: "transitions" or "all" (docs/isosurf.md 5.2)
};

struct ProgressiveArgs {
  std::string errors;      // "E0,E1,...,0" descending
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

}  // namespace fest::isosurf
