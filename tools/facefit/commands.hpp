#pragma once
// The subcommands of facefit; main.cpp maps flags onto these structs.

#include <string>
#include <vector>

namespace facefit_tool {

struct FitArgs {
  std::string model, landmarks = "-", map, camera = "similarity", center = "150,150", eta = "2", eta_units = "mm2";
  std::string space = "model", texture;
  std::string nuisance = "free", full_shape, coeffs, report, batch, output = "-", to, uncertainty;
  double scale = 1, yaw = 0, noise_sigma = 0, nuisance_sigma = 100, pts_origin = 1;
  bool noise_sigma_given = false, eta_given = false, skip_unmapped = false, fix_basis = false;
  int components = 0, iterations = 5, threads = 0;
};
int run_fit(const FitArgs& a);

struct BuildArgs {
  std::string output, list, landmarks, units = "mm", mask;
  std::vector<std::string> examples;
  int components = 0;
  double variance = 0;
  bool f64 = false;
};
int run_build(const BuildArgs& a);

struct ConvertArgs {
  std::string from, input, output, landmarks, mask;
  double scale = 1;
  bool fix_basis = false;
};
int run_convert(const ConvertArgs& a);

struct InfoArgs {
  std::string model;
  bool fix_basis = false;
};
int run_info(const InfoArgs& a);

struct SampleArgs {
  std::string model, coeffs, output = "-", to;
  int random = 0;
  double sigma_scale = 1;
  unsigned long long seed = 1;
};
int run_sample(const SampleArgs& a);

struct ProjectArgs {
  std::string model, mesh, vertices, center = "150,150";
  double scale = 1, yaw = 0, pitch = 0, noise_sigma = 0;
  unsigned long long seed = 1;
  bool by_vertex = false;
};
int run_project(const ProjectArgs& a);

struct EvalArgs {
  std::string truth, estimate, mask, output = "-", png;
  bool per_vertex = false;
};
int run_eval(const EvalArgs& a);

struct SweepArgs {
  std::string model, faces, vertices, etas = "0,1e-4,1e-3,1e-2,0.1,0.3,1,2,3,10,100,1000", components, noise = "0", yaw = "0",
                                       mask;
  bool summary = false;
  unsigned long long seed = 1;
};
int run_sweep(const SweepArgs& a);

struct SynthArgs {
  std::string output;
  int faces = 200, train = 100, resolution = 128;
  double detail = 1;
  unsigned long long seed = 1;
};
int run_synth(const SynthArgs& a);

}  // namespace facefit_tool
