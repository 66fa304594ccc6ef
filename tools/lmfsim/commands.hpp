#pragma once
// The subcommands of lmfsim; main.cpp parses flags into these structs and calls them.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lmfsim/model.hpp"

namespace lmfsim_tool {

// Command-line overrides of the scene's `sim` block (spec §4).
struct SimOverrides {
  std::optional<double> dt, t_end, alpha, beta, kappa, omega0, zeta, svd_tol, max_violation, rtol, atol;
  std::optional<int> every;
  std::string integrator, solver, formulation, stab;
  void apply(fest::lmfsim::SimSettings& sim) const;
};

struct RunOptions {
  SimOverrides sim;
  bool wide = false, stream = false;
  std::string forces, diag, report;
};

// Reads the scene JSON (bytes) into a Scene, meshes from files relative to the cwd.
fest::lmfsim::Scene load_scene(const std::string& bytes);

// run, check, assemble and reduced read the scene JSON from standard input.
int cmd_run(const RunOptions& opt);
int cmd_check(const SimOverrides& sim);
int cmd_assemble();

struct GenOptions {
  std::string kind;
  int n = 2;
  std::string type = "box", joint;
  double mass = 1, length = 1, angle = 90;
  bool planar = false;
  std::string abcd = "0.3,1,0.8,1";
  int gravity = 1;
  double omega0 = 0;
};
int cmd_gen(const GenOptions& opt);

struct ReducedOptions {
  bool chain = false, fourbar = false;
  SimOverrides sim;
};
int cmd_reduced(const ReducedOptions& opt);

struct ExportOptions {
  std::string scene, vtk, obj, ply, trajectory = "-";
};
int cmd_export(const ExportOptions& opt);

struct DiffOptions {
  std::string a, b;
  std::vector<std::string> bodies;
  std::optional<double> at;
};
int cmd_diff(const DiffOptions& opt);

}  // namespace lmfsim_tool
