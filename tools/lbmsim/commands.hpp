#pragma once
// lbmsim's subcommands: typed options as main.cpp parses them, one function each.

#include <optional>
#include <string>
#include <vector>

#include "lbm/case.hpp"
#include "lbm/case_json.hpp"
#include "lbm/solver.hpp"

namespace fest::lbmsim_tool {

// Where run's fields go: the frame stream on standard output, VTI series or NRRD files.
enum class FieldFormat { stream, vti, nrrd };

struct RunOptions {
  std::string case_file = "-";
  std::string output;          // pattern with %d, "-" or "": the frame stream
  FieldFormat format = FieldFormat::stream;  // from --to, else the pattern's extension
  std::optional<std::vector<std::string>> fields;  // none: the case's
  long every = -1;             // -1: the case's
  long steps = -1;             // -1: the case's
  lbm::Precision precision = lbm::Precision::f64;
  std::string forces, probes, report;
  std::vector<lbm::CaseOverride> set;
  std::optional<bool> compress;  // none: the case's
  bool quiet = false;
  bool progress = false;  // --progress: time steps done (rank 0 draws)
};

struct CheckOptions {
  std::string which = "all-fast";
  int n = 0;
  std::string report;
  bool progress = false;  // --progress: runs done, or convergence towards the steady state
};

struct BenchOptions {
  lbm::LatticeKind lattice = lbm::LatticeKind::d3q19;
  int size = 0;                // 0: 128 (d3q19) / 1024 (d2q9)
  int steps = 0;               // 0: by size
  std::vector<lbm::Precision> precision{lbm::Precision::f64};
  std::vector<int> threads{1};
  lbm::CollisionModel collision = lbm::CollisionModel::bgk;
};

struct VoxelizeOptions {
  std::string mesh;
  std::vector<int> size{64, 64, 64};
  bool fit_box = true;         // --fit box; false: --fit none
  double margin = 2.0;
  std::string output = "-";
};

struct InfoOptions {
  std::string case_file = "-";
  std::vector<lbm::CaseOverride> set;
  lbm::Precision precision = lbm::Precision::f64;
  bool json = false;
};

// "double" or "float", as --precision spells them (reports, bench lines).
const char* precision_name(lbm::Precision p) noexcept;

int run_command(const RunOptions& o);
int check_command(const CheckOptions& o);
int bench_command(const BenchOptions& o);
int voxelize_command(const VoxelizeOptions& o);
int info_command(const InfoOptions& o);

// "with MPI (Open MPI 4.1)" or "without MPI", for --version.
std::string build_features();
void set_threads(int threads);

}  // namespace fest::lbmsim_tool
