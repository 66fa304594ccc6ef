#pragma once
// fluidsim's subcommands: options as parsed by main.cpp, one function per subcommand.

#include <string>
#include <vector>

namespace fest::fluidsim_tool {

struct RunOptions {
  std::string scene = "-";
  std::string output = "-";
  std::string to;
  std::string fields;
  int frames = 0;        // 0: the scene's
  int interp = 0;        // 0: the scene's
  std::string poisson;   // "": by size
  int iters = 20;
  double tol = 1e-8;
  std::string order = "paper";
  std::string grid = "collocated";
  std::string precision = "float";
  bool mass_correct = false;
  std::string pipeline = "on";
  std::string report, stats;
  bool progress = false;
  bool quiet = false;
  int threads = 0;       // 0: all cores
};

struct RenderOptions {
  std::string input = "-";
  std::string output = "-";
  std::string to = "png";
  std::string mode = "absorb";
  std::string axis = "z";
  int index = -1;
  std::string field = "density";
  std::vector<double> range;
  std::string colormap = "inferno";
  double sigma = 0.0;   // 0: 4 / (domain length) so a full-density column is mostly opaque
  int depth = 8;
};

struct InterpOptions {
  std::string a, b;
  double alpha = 0.5;
  std::string output = "-";
};

struct CheckOptions {
  std::string which = "all";
  int n = 0;
  double dt = 0.0;
  double nu = 0.01;
  std::string report;
  int threads = 0;       // 0: all cores
};

struct BenchOptions {
  std::vector<int> sizes{31, 64};
  std::vector<int> threads{1, 2};
  int steps = 5;
  double nu = 1e-4;
  std::vector<std::string> poisson{"fdm", "fft", "mg", "gs"};
};

int run_command(const RunOptions& o);
int render_command(const RenderOptions& o);
int interp_command(const InterpOptions& o);
int check_command(const CheckOptions& o);
int bench_command(const BenchOptions& o);

// Sets the OpenMP thread count (--threads of run and check; 0: all cores).
void set_threads(int threads);

}  // namespace fest::fluidsim_tool

// Shared between run and render: a rendered plane as an 8/16-bit RGB image, and output
// names from a pattern with one printf-style integer conversion (%d, %05d).
#include <opencv2/core.hpp>
#include "fluidsim/render.hpp"
namespace fest::fluidsim_tool {
cv::Mat plane_to_rgb(const fluidsim::Plane& plane, double lo, double hi, const std::string& colormap, int depth);
cv::Mat plane_to_float(const fluidsim::Plane& plane);
bool has_index_conversion(const std::string& pattern);
int omp_threads();
double peak_rss_mb();
std::string expand_pattern(const std::string& pattern, long index);
}  // namespace fest::fluidsim_tool
