#pragma once
// lbmsim's subcommands: typed options as main.cpp parses them, one function each.

#include <string>
#include <vector>

namespace fest::lbmsim {

struct RunOptions {
  std::string case_file = "-";
  std::string output;          // pattern with %d, "-" or "": the frame stream
  std::string to;              // vti, nrrd, stream
  std::string fields;          // comma-separated; "" : the case's
  long every = -1;             // -1: the case's
  long steps = -1;             // -1: the case's
  std::string precision = "double";
  std::string forces, probes, report;
  std::vector<std::string> set;
  std::string compress;        // on/off ("" : the case's)
  bool quiet = false;
};

struct CheckOptions {
  std::string which = "all-fast";
  int n = 0;
  std::string report;
};

struct BenchOptions {
  std::string lattice = "d3q19";
  int size = 0;                // 0: 128 (d3q19) / 1024 (d2q9)
  int steps = 0;               // 0: by size
  std::vector<std::string> precision{"double"};
  std::vector<int> threads{1};
  std::string collision = "bgk";
};

struct VoxelizeOptions {
  std::string mesh;
  std::vector<int> size{64, 64, 64};
  std::string fit = "box";
  double margin = 2.0;
  std::string output = "-";
};

struct InfoOptions {
  std::string case_file = "-";
  std::vector<std::string> set;
  std::string precision = "double";
  bool json = false;
};

int run_command(const RunOptions& o);
int check_command(const CheckOptions& o);
int bench_command(const BenchOptions& o);
int voxelize_command(const VoxelizeOptions& o);
int info_command(const InfoOptions& o);

// "with MPI (Open MPI 4.1)" or "without MPI", for --version.
std::string build_features();
void set_threads(int threads);

}  // namespace fest::lbmsim
