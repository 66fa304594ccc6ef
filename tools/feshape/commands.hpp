#pragma once
// feshape's subcommands (docs/feshape.md §4), each taking its parsed options.

#include <cstdint>
#include <string>
#include <vector>

namespace fest::feshape_tool {

enum class PointsFormat { automatic, xyz, mesh };  // --in-format: auto recognises by content
enum class InitRule { automatic, given };          // --init: auto unless --qs gives the shape
enum class FitSolver { equilibrium, explicit_euler, semi_implicit };

// The model's start: grid, global parameters (or auto) and pose.
struct ModelArgs {
  int rings = 8, meridians = 8;     // --grid MxN, each in 3..1000
  std::vector<double> qs;           // 11 values; empty = --init auto (fit) / unit sphere
  std::vector<double> center;       // 3 values
  std::vector<double> quat;         // w,x,y,z
};

struct FitArgs {
  std::string input = "-";          // points (.xyz rows or a mesh's vertices)
  std::string output = "-";
  std::string to;                   // ply, plya, obj, off
  PointsFormat in_format = PointsFormat::automatic;
  ModelArgs model;
  InitRule init = InitRule::automatic;
  std::vector<double> w{0.5, 0.5, 0.5, 0, 0, 0};  // w00,w01,w10,w02,w11,w20
  double beta = 20;
  FitSolver solver = FitSolver::equilibrium;
  double dt = 1e-5;
  std::vector<double> damping{1, 1, 1, 1};
  double move_tol = 0;              // 0 = 5e-5 x half the data's bounding-box diagonal
  int max_iter = 0;                 // 0 = 200 (equilibrium) or 200000 (Euler)
  int levels = 3;
  double tau = 0.05;
  long long max_nodes = 100000;
  int reassign_every = 1;
  bool no_global_phase = false;
  std::string levels_out;           // pattern with %s
  std::string partial;              // on a failure after some levels: the last one
  std::string report;
  int threads = 0;
  bool progress = false;  // --progress: levels, iterations within each
};

struct SampleArgs {
  std::string output = "-";
  ModelArgs model;
  long long n = 2000;
  double noise = 0;
  std::vector<double> bumps;        // K,AMP
  std::uint64_t seed = 1;
};

struct EvalArgs {
  std::string input = "-";          // mesh
  std::string points;               // points file
  PointsFormat in_format = PointsFormat::automatic;
  std::string output = "-";         // JSON
  int threads = 0;
};

struct InitArgs {
  std::string output = "-";
  std::string to;
  ModelArgs model;
};

int run_fit(const FitArgs& a);
int run_sample(const SampleArgs& a);
int run_eval(const EvalArgs& a);
int run_init(const InitArgs& a);

}  // namespace fest::feshape_tool
