#pragma once
// radiosity's command library (fest_radiosity_app): typed options and one function per
// subcommand. main.cpp maps flags onto these; tests and benchmarks call them directly.

#include <string>
#include <vector>

#include "radiosity/form_factors.hpp"
#include "radiosity/solver.hpp"

namespace fest::radiosity_tool {

struct SolveArgs {
  std::string scene = "-";   // JSON scene (or - for standard input)
  std::string output = "-";  // lit PLY
  radiosity::Engine ff = radiosity::Engine::hybrid;
  int hemicube_res = 256;
  int samples = 16;
  radiosity::Solver solver = radiosity::Solver::orpr;
  double omega = -1;  // < 0: the solver's default
  double tol = 1e-3;
  long max_shots = 0;
  int levels = 2;
  double grad = 0.05;
  double min_element = 0;
  double patch_size = 0, element_size = 0;
  bool no_mesh = false;
  double crease = 20;
  bool emission_is_radiance = true;  // --emission radiance (x pi) or exitance
  double exposure = 0;
  std::string split_objects;  // directory: one PLY per object
  std::string log;            // per-shot CSV
  std::string report;         // JSON report
  std::string view;           // PNG rendered through lib/reflectance's rasteriser
  int view_width = 512;
  bool direct = false;
  bool strict = false;
  bool quiet = false;
  bool progress = false;  // --progress: the unshot fraction on its way down to --tol
  int threads = 0;
};

struct CornellArgs {
  bool no_blocks = false;
  std::string output = "-";
};

struct FormFactorArgs {
  std::string a, b;  // two meshes of one planar polygon each
  radiosity::Engine ff = radiosity::Engine::analytic;
  int hemicube_res = 256;
  int samples = 16;
  int cells = 16;
  int threads = 0;
};

struct CameraArgs {
  std::vector<double> eye, target, up;  // empty: the default view of the scene's box
  double fov = 39.30746768437243;       // vertical, degrees (the Cornell camera's)
  int width = 512, height = 0;          // height 0: square
};

struct RenderArgs {
  std::string input = "-";
  std::string output = "-";
  CameraArgs camera;
  int threads = 0;
};

int run_solve(const SolveArgs& args, const CameraArgs& camera);
int run_cornell(const CornellArgs& args);
int run_formfactor(const FormFactorArgs& args);
int run_render(const RenderArgs& args);

}  // namespace fest::radiosity_tool
