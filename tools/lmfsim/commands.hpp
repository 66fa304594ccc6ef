#pragma once
// The subcommands of lmfsim; main.cpp parses flags into these structs and calls them.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lmfsim/model.hpp"

namespace fest::lmfsim_tool {

// Command-line overrides of the scene's `sim` block (docs/lmfsim.md §4).
struct SimOverrides {
  std::optional<double> dt, t_end, alpha, beta, kappa, omega0, zeta, svd_tol, max_violation, rtol, atol;
  std::optional<int> every;
  std::optional<fest::lmfsim::Integrator> integrator;
  std::optional<fest::lmfsim::SolverKind> solver;
  std::optional<fest::lmfsim::Formulation> formulation;
  std::optional<fest::lmfsim::Stabilization> stab;
  // Sets the overridden values and checks dt, t_end, every and the step count (usage
  // errors naming the flags).
  void apply(fest::lmfsim::SimSettings& sim) const;
};

// Steps of a run: 1e9 steps of even the cheapest scene take hours, and the frame number
// they give stays an int.
constexpr double kMaxSteps = 1e9;
// round(t_end / dt), checked against kMaxSteps in double first: a usage error naming
// --t-end/--dt when either came from a flag, else bad input naming the scene's values.
long step_count(double t_end, double dt, bool from_flags);

struct RunOptions {
  SimOverrides sim;
  bool wide = false, stream = false;
  std::string forces, diag, report;
  int threads = 0;  // accepted; the integrator is sequential (one thread)
  bool progress = false;  // --progress: simulated time of t_end
};

// Reads the scene JSON (bytes) into a Scene, meshes from files relative to the cwd.
fest::lmfsim::Scene load_scene(const std::string& bytes);

// run, check, assemble and reduced read the scene JSON from standard input.
int cmd_run(const RunOptions& opt);
int cmd_check(const SimOverrides& sim);
int cmd_assemble();

enum class GenScene { chain, fourbar, activation, sleigh, bead, motorarm, ring };
enum class LinkType { box, rod, particle };
enum class JointType { ball, hinge, distance };

// Links of `gen chain`/`gen ring`: the scene JSON of a link takes about 5 KB while it is
// built (4.8 KB measured at 100000 links), and a million links is already a scene of
// 600 MB; cmd_gen also checks the machine's memory.
constexpr int kMaxLinks = 1000000;
constexpr double kGenBytesPerLink = 8192;

struct GenOptions {
  GenScene kind = GenScene::chain;
  int n = 2;
  LinkType type = LinkType::box;
  std::optional<JointType> joint;  // none: ball; hinge with --planar; distance for particles
  double mass = 1, length = 1, angle = 90;
  bool planar = false;
  std::array<double, 4> abcd{0.3, 1, 0.8, 1};  // crank, coupler, rocker, ground
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

}  // namespace fest::lmfsim_tool
