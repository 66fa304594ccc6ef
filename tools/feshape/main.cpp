// feshape: hierarchical shape fitting with deformable superquadrics (tapering, bending)
// and locally adaptive finite elements refined by Rivara bisection (docs/feshape.md).
//
// Wiring only: this file maps flags onto commands.hpp.

#include "cli/cli.hpp"
#include "commands.hpp"
#include "model_args.hpp"

namespace {

using fest::feshape_tool::PointsFormat;

void add_model_flags(CLI::App& app, fest::feshape_tool::ModelArgs& m) {
  app.add_option_function<std::string>(
         "--grid", [&m](const std::string& g) { fest::feshape_tool::parse_grid(g, m.rings, m.meridians); },
         "Initial lat-long mesh MxN (rings x meridians): V = MN + 2")
      ->default_str("8x8");
  app.add_option("--qs", m.qs, "Global parameters a,a1,a2,a3,e1,e2,t1,t2,b1,b2,b3")->delimiter(',')->expected(11);
  app.add_option("--center", m.center, "Model centre x,y,z")->delimiter(',')->expected(3);
  app.add_option("--quat", m.quat, "Model rotation as a quaternion w,x,y,z")->delimiter(',')->expected(4);
}

void add_points_format(CLI::App& app, PointsFormat& format) {
  app.add_option_function<std::string>(
      "--in-format",
      [&format](const std::string& w) {
        if (w == "auto") format = PointsFormat::automatic;
        else if (w == "xyz") format = PointsFormat::xyz;
        else if (w == "mesh") format = PointsFormat::mesh;
        else throw fest::usage_error("--in-format {}: expected auto, xyz or mesh", w);
      },
      "Points format: auto, xyz, mesh");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::feshape_tool;
  CLI::App app{"Fit a deformable superquadric (pose, 11 global parameters: size, squareness, tapering,\n"
               "bending) plus locally adaptive finite-element displacements to 3-D points; a mesh per level.",
               "feshape"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  FitArgs fa;
  auto* fit = app.add_subcommand("fit", "Points (.xyz rows or a mesh's vertices) -> fitted model mesh (final level)");
  fit->add_option("input", fa.input, "Points file, - = standard input");
  fit->add_option("-o,--output", fa.output, "Mesh of the final level (.ply .obj .off), - = standard output (binary PLY)");
  fit->add_option("--to", fa.to, "Output format: ply, plya (ascii PLY), obj, off");
  add_points_format(*fit, fa.in_format);
  add_model_flags(*fit, fa.model);
  fit->add_option_function<std::string>(
      "--init",
      [&fa](const std::string& w) {
        if (w == "auto") fa.init = InitRule::automatic;
        else if (w == "given") fa.init = InitRule::given;
        else throw fest::usage_error("--init {}: expected auto or given", w);
      },
      "auto (centroid, principal axes, extents) unless --qs is given");
  fit->add_option("--w", fa.w, "Stiffness w00,w01,w10,w02,w11,w20 (eq. 7)")->delimiter(',')->expected(6);
  fit->add_option("--beta", fa.beta, "Force strength beta (eq. 10)");
  fit->add_option_function<std::string>(
      "--solver,--integrator",
      [&fa](const std::string& w) {
        if (w == "equilibrium") fa.solver = FitSolver::equilibrium;
        else if (w == "explicit") fa.solver = FitSolver::explicit_euler;
        else if (w == "semi-implicit") fa.solver = FitSolver::semi_implicit;
        else throw fest::usage_error("--solver {}: expected equilibrium, explicit or semi-implicit", w);
      },
      "equilibrium (LM + sparse solve), explicit (seed's Euler), semi-implicit");
  fit->add_option("--dt", fa.dt, "Euler time step (explicit solvers)");
  fit->add_option("--damping", fa.damping, "D per block dc,dtheta,ds,dd (explicit solvers)")->delimiter(',')->expected(4);
  fit->add_option("--move-tol", fa.move_tol, "Converged when no node moves farther per iteration (default 5e-5 x half diagonal)");
  fit->add_option("--max-iter", fa.max_iter, "Iterations per level (default 200 equilibrium, 200000 Euler)")->check(fest::cli::range(1, 1000000000));
  fit->add_option("--levels", fa.levels, "Subdivision levels after level 0")->check(fest::cli::range(0, 20));
  fit->add_option("--tau", fa.tau, "Points farther than this select elements for bisection");
  fit->add_option("--max-nodes", fa.max_nodes, "Node limit: reaching it is a failure")->check(fest::cli::range(6, 100000000));
  fit->add_option("--reassign-every", fa.reassign_every, "Force assignment every K iterations")->check(fest::cli::range(1, 1000000000));
  fit->add_flag("--no-global-phase", fa.no_global_phase, "Start with global + local at once (no level G)");
  fit->add_option("--levels-out", fa.levels_out, "Write every level: a path with %s (G, 0, 1, ...)");
  fit->add_option("--partial", fa.partial, "On a failure after some levels (node limit): write the last finished one here");
  fit->add_option("--report", fa.report, "JSON: parameters and the per-level table (nodes, elements, errors)");
  fest::cli::add_threads(*fit, fa.threads);
  fest::cli::add_progress(*fit, fa.progress);

  SampleArgs sa;
  auto* sample = app.add_subcommand("sample", "Points on a deformable superquadric (x y z rows)");
  add_model_flags(*sample, sa.model);
  sample->add_option("-o,--output", sa.output, "Points file, - = standard output");
  sample->add_option("--n", sa.n, "Number of points")->check(fest::cli::range(1, 10000000));
  sample->add_option("--noise", sa.noise, "Gaussian noise sigma (absolute)");
  sample->add_option("--bumps", sa.bumps, "K,AMP: K radial Gaussian bumps of height AMP*a")->delimiter(',')->expected(2);
  sample->add_option("--seed", sa.seed, "Random seed");

  EvalArgs ea;
  auto* eval = app.add_subcommand("eval", "Distances of points to a mesh: mean, max, std, var (JSON)");
  eval->add_option("input", ea.input, "Mesh, - = standard input");
  eval->add_option("--points", ea.points, "Points file (.xyz rows or a mesh's vertices)")->required();
  add_points_format(*eval, ea.in_format);
  eval->add_option("-o,--output", ea.output, "JSON, - = standard output");
  fest::cli::add_threads(*eval, ea.threads);

  InitArgs ia;
  auto* init = app.add_subcommand("init", "The initial model (lat-long mesh on the global shape) as a mesh");
  add_model_flags(*init, ia.model);
  init->add_option("-o,--output", ia.output, "Mesh file, - = standard output (binary PLY)");
  init->add_option("--to", ia.to, "Output format: ply, plya, obj, off");

  return fest::cli::run(app, argc, argv, [&] {
    if (*fit) return run_fit(fa);
    if (*sample) return run_sample(sa);
    if (*eval) return run_eval(ea);
    return run_init(ia);
  });
}
