// lmfsim: constrained rigid-body dynamics with Lagrange multipliers (docs/lmfsim.md).
// Wiring only: flags -> typed options -> commands (tools/lmfsim/cmd_<sub>.cpp) -> lib/lmfsim.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/number_list.hpp"
#include "commands.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::lmfsim_tool;
namespace lm = fest::lmfsim;

// Binds an optional enum to a flag of words (checked like CLI::IsMember).
template <typename E>
void opt_words(CLI::App* app, const std::string& name, std::optional<E>& target, const std::string& help,
               std::vector<std::pair<std::string, E>> words) {
  fest::cli::enum_words(app->add_option_function<E>(name, [&target](const E& v) { target = v; }, help), std::move(words));
}

GenScene gen_scene(const std::string& kind) {
  if (kind == "chain") return GenScene::chain;
  if (kind == "fourbar") return GenScene::fourbar;
  if (kind == "activation") return GenScene::activation;
  if (kind == "sleigh") return GenScene::sleigh;
  if (kind == "bead") return GenScene::bead;
  if (kind == "motorarm") return GenScene::motorarm;
  if (kind == "ring") return GenScene::ring;
  throw fest::usage_error("unknown scene '{}' (chain, fourbar, activation, sleigh, bead, motorarm, ring)", kind);
}

// gen's words and lists, into the typed options.
void resolve_gen(GenOptions& gen, const std::string& kind, const std::string& joint, const std::string& abcd) {
  gen.kind = gen_scene(kind);
  if (joint == "ball") gen.joint = JointType::ball;
  else if (joint == "hinge") gen.joint = JointType::hinge;
  else if (joint == "distance") gen.joint = JointType::distance;
  else if (!joint.empty()) throw fest::usage_error("--joint must be ball, hinge or distance");
  const std::vector<double> v = fest::cli::number_list(abcd, 4, 4, "--abcd");
  for (double x : v)
    if (!(x > 0)) throw fest::usage_error("--abcd lengths must be positive");
  for (int k = 0; k < 4; ++k) gen.abcd[static_cast<std::size_t>(k)] = v[static_cast<std::size_t>(k)];
}

// Binds an optional<double> to a flag.
template <typename T>
CLI::Option* opt_value(CLI::App* app, const std::string& name, std::optional<T>& target, const std::string& help) {
  return app->add_option_function<T>(name, [&target](const T& v) { target = v; }, help);
}

void add_sim_flags(CLI::App* app, SimOverrides& s, bool full) {
  opt_value(app, "--dt", s.dt, "Time step in seconds (default: scene, else 1e-3)");
  opt_value(app, "--t-end", s.t_end, "End time in seconds (default: scene)");
  if (!full) return;
  opt_value(app, "--every", s.every, "Write a frame every N steps (default 10)")->check(fest::cli::range(1, 1000000000));
  opt_words<lm::Integrator>(app, "--integrator", s.integrator, "rk4 (default), rk45, symplectic or euler",
                            {{"rk4", lm::Integrator::rk4},
                             {"rk45", lm::Integrator::rk45},
                             {"symplectic", lm::Integrator::symplectic},
                             {"euler", lm::Integrator::euler}});
  opt_words<lm::SolverKind>(app, "--solver", s.solver, "baraff (O(n), default) or dense",
                            {{"baraff", lm::SolverKind::baraff}, {"dense", lm::SolverKind::dense}});
  opt_words<lm::Formulation>(app, "--formulation", s.formulation, "lmf (default) or penalty",
                             {{"lmf", lm::Formulation::lmf}, {"penalty", lm::Formulation::penalty}});
  opt_words<lm::Stabilization>(app, "--stab", s.stab, "Stabilisation: baumgarte (default), force, project, none",
                               {{"baumgarte", lm::Stabilization::baumgarte},
                                {"force", lm::Stabilization::force},
                                {"project", lm::Stabilization::project},
                                {"none", lm::Stabilization::none}});
  opt_value(app, "--alpha", s.alpha, "Baumgarte alpha in 1/s (default 10)");
  opt_value(app, "--beta", s.beta, "Baumgarte beta in 1/s (default 10)");
  opt_value(app, "--kappa", s.kappa, "Penalty stiffness scale in kg (default 1)");
  opt_value(app, "--omega0", s.omega0, "Penalty natural frequency in 1/s (default 100)");
  opt_value(app, "--zeta", s.zeta, "Penalty damping ratio (default 1)");
  opt_value(app, "--svd-tol", s.svd_tol, "Relative singular value cut-off of the auxiliary solve (default 1e-10)");
  opt_value(app, "--max-violation", s.max_violation, "Fail when |C| exceeds this (default 0.01 * length scale)");
  opt_value(app, "--rtol", s.rtol, "rk45 relative tolerance (default 1e-8)");
  opt_value(app, "--atol", s.atol, "rk45 absolute tolerance (default 1e-10)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Constrained rigid-body dynamics with Lagrange multipliers: JSON scene in, trajectory CSV out", "lmfsim"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Simulate the scene on standard input; trajectory CSV on standard output");
  add_sim_flags(run_cmd, run.sim, true);
  run_cmd->add_flag("--wide", run.wide, "One row per frame with <body>.<field> columns");
  run_cmd->add_option("--forces", run.forces, "Write multipliers and constraint forces per frame to FILE (CSV)");
  run_cmd->add_option("--diag", run.diag, "Write energy and drift diagnostics per frame to FILE (CSV)");
  run_cmd->add_option("--report", run.report, "Write a JSON summary (steps/s, drift, max |C|) to FILE");
  run_cmd->add_flag("--stream", run.stream, "Write frames as they come; a failure ends the stream with '# ERROR'");
  fest::cli::add_progress(*run_cmd, run.progress);
  run_cmd->add_option("--threads", run.threads,
                      "Accepted for the common interface; the integrator is sequential and runs one thread")
      ->default_val(0);

  SimOverrides check_sim;
  auto* check_cmd = app.add_subcommand("check", "Topology, rank and degrees of freedom of the scene (JSON)");
  add_sim_flags(check_cmd, check_sim, true);

  auto* assemble_cmd = app.add_subcommand("assemble", "Project the initial state onto the constraints; scene JSON out");

  GenOptions gen;
  std::string gen_kind, gen_joint, gen_abcd = "0.3,1,0.8,1";
  auto* gen_cmd = app.add_subcommand("gen", "Write a test scene: chain, fourbar, activation, sleigh, bead, motorarm, ring");
  gen_cmd->add_option("kind", gen_kind, "chain, fourbar, activation, sleigh, bead, motorarm or ring")->required();
  gen_cmd->add_option("--n", gen.n, "Links (chain, ring)")->check(fest::cli::range(1, kMaxLinks));
  fest::cli::enum_words<LinkType>(gen_cmd->add_option("--type", gen.type, "Link type: box, rod or particle"),
                        {{"box", LinkType::box}, {"rod", LinkType::rod}, {"particle", LinkType::particle}});
  gen_cmd->add_option("--joint", gen_joint, "ball, hinge or distance (default: ball; hinge with --planar; distance for particles)");
  gen_cmd->add_option("--mass", gen.mass, "Total mass in kg (default 1)");
  gen_cmd->add_option("--length", gen.length, "Total length in m (default 1)");
  gen_cmd->add_option("--angle", gen.angle, "Initial angle from the downward vertical, degrees (fourbar: crank angle)");
  gen_cmd->add_flag("--planar", gen.planar, "Hinges about y (motion in the x-z plane)");
  gen_cmd->add_option("--abcd", gen_abcd, "Four-bar lengths crank,coupler,rocker,ground (default 0.3,1,0.8,1)");
  gen_cmd->add_option("--gravity", gen.gravity, "1: g = 9.81 along -z (default), 0: none")->check(CLI::IsMember({0, 1}));
  gen_cmd->add_option("--omega0", gen.omega0, "Initial crank rate in rad/s (fourbar)");

  ReducedOptions red;
  auto* red_cmd = app.add_subcommand("reduced", "Reduced-coordinate reference trajectory (planar chains, four-bar)");
  red_cmd->add_flag("--chain", red.chain, "Planar open chain about parallel hinge axes");
  red_cmd->add_flag("--fourbar", red.fourbar, "Planar four-bar linkage (layout of `gen fourbar`)");
  add_sim_flags(red_cmd, red.sim, false);

  ExportOptions ex;
  auto* ex_cmd = app.add_subcommand("export", "Per-frame meshes of the trajectory on standard input");
  ex_cmd->add_option("--scene", ex.scene, "The scene the trajectory came from")->required();
  ex_cmd->add_option("--vtk", ex.vtk, "Folder for frame_NNNNNN.vtp and scene.pvd (ParaView)");
  ex_cmd->add_option("--obj", ex.obj, "Folder for one OBJ per frame");
  ex_cmd->add_option("--ply", ex.ply, "Folder for one PLY per frame");

  DiffOptions df;
  auto* df_cmd = app.add_subcommand("diff", "Position/angle differences of two trajectories (JSON)");
  df_cmd->add_option("a", df.a, "First trajectory CSV")->required();
  df_cmd->add_option("b", df.b, "Second trajectory CSV")->required();
  df_cmd->add_option("--bodies", df.bodies, "Only these bodies (comma-separated)")->delimiter(',')->allow_extra_args(false);
  opt_value(df_cmd, "--at", df.at, "Also report the difference at the frame nearest to this time");

  return fest::cli::run(app, argc, argv, [&]() -> int {
    if (run_cmd->parsed()) return cmd_run(run);
    if (check_cmd->parsed()) return cmd_check(check_sim);
    if (assemble_cmd->parsed()) return cmd_assemble();
    if (gen_cmd->parsed()) {
      resolve_gen(gen, gen_kind, gen_joint, gen_abcd);
      return cmd_gen(gen);
    }
    if (red_cmd->parsed()) return cmd_reduced(red);
    if (ex_cmd->parsed()) return cmd_export(ex);
    if (df_cmd->parsed()) return cmd_diff(df);
    return 2;
  });
}
