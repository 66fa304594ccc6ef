#pragma once
// fluidsim's subcommands: options as parsed by main.cpp, one function per subcommand
// (cmd_<sub>.cpp).

#include <optional>
#include <string>
#include <vector>

#include "fluidsim/projection.hpp"
#include "fluidsim/render.hpp"

namespace fest::fluidsim_tool {

// Where run's frames go: the NRRD frame stream on standard output, or files.
enum class FrameFormat { stream, vti, nrrd, pfm, exr, png };
// Step order: the paper's, or Stam 2003's (compact Laplacian).
enum class StepOrder { paper, stam03 };

struct RunOptions {
  std::string scene = "-";
  std::string output = "-";             // pattern with %d, or "-"
  FrameFormat format = FrameFormat::stream;
  std::vector<std::string> fields;      // empty: velocity and every scalar
  int frames = 0;                       // 0: the scene's
  int interp = 0;                       // 0: the scene's
  std::optional<fluidsim::PoissonSolver> poisson;  // none: by size
  int iters = 20;
  double tol = 1e-8;
  StepOrder order = StepOrder::paper;
  bool float64 = false;                 // --precision double
  bool mass_correct = false;
  bool pipeline = true;
  std::string report, stats;
  bool progress = false;
  bool quiet = false;
  int threads = 0;                      // 0: all cores
};

enum class ImageFormat { png, pfm };

struct RenderOptions {
  std::string input = "-";
  std::string output = "-";
  ImageFormat to = ImageFormat::png;
  fluidsim::RenderMode mode = fluidsim::RenderMode::absorb;
  int axis = 2;                         // z
  int index = -1;
  std::string field = "density";
  std::vector<double> range;
  fluidsim::Colormap colormap = fluidsim::Colormap::inferno;
  double sigma = 0.0;   // 0: 4 / (domain length) so a full-density column is mostly opaque
  int depth = 8;
  bool progress = false;  // --progress: frames rendered
};

struct InterpOptions {
  std::string a, b;
  double alpha = 0.5;
  std::string output = "-";
};

// The analytic cases of `check` (docs/fluidsim.md), or all of them.
enum class CheckCase { taylor_green, abc, projection, interp, mass, stability, all };

struct CheckOptions {
  CheckCase which = CheckCase::all;
  int n = 0;
  double dt = 0.0;
  double nu = 0.01;
  std::string report;
  int threads = 0;       // 0: all cores
  bool progress = false;  // --progress: cases done
};

struct BenchOptions {
  std::vector<int> sizes{31, 64};
  std::vector<int> threads{1, 2};
  int steps = 5;
  double nu = 1e-4;
  std::vector<fluidsim::PoissonSolver> poisson{fluidsim::PoissonSolver::fdm, fluidsim::PoissonSolver::fft,
                                               fluidsim::PoissonSolver::mg, fluidsim::PoissonSolver::gs};
};

int run_command(const RunOptions& o);
int render_command(const RenderOptions& o);
int interp_command(const InterpOptions& o);
int check_command(const CheckOptions& o);
int bench_command(const BenchOptions& o);

}  // namespace fest::fluidsim_tool
