// feshape fit: points -> model hierarchy (docs/feshape.md §2.3, §4), the final level on the
// output, every level with --levels-out, the per-level table with --report.
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "feshape/fit.hpp"
#include "model_args.hpp"
#include "model_output.hpp"
#include "points_input.hpp"

namespace fest::feshape_tool {
namespace {

feshape::FitOptions fit_options(const FitArgs& a) {
  feshape::FitOptions o;
  if (a.w.size() != 6) throw usage_error("--w needs 6 weights w00,w01,w10,w02,w11,w20");
  for (double w : a.w)
    if (!(w >= 0) || !std::isfinite(w)) throw usage_error("--w: weights must be finite and >= 0");
  o.weights = {a.w[0], a.w[1], a.w[2], a.w[3], a.w[4], a.w[5]};
  if (!(a.beta > 0) || !std::isfinite(a.beta)) throw usage_error("--beta must be > 0");
  o.beta = a.beta;
  o.solver = a.solver == FitSolver::explicit_euler ? feshape::Solver::explicit_euler
             : a.solver == FitSolver::semi_implicit ? feshape::Solver::semi_implicit
                                                    : feshape::Solver::equilibrium;
  if (!(a.dt > 0) || !std::isfinite(a.dt)) throw usage_error("--dt must be > 0");
  o.dt = a.dt;
  if (a.damping.size() != 4) throw usage_error("--damping needs 4 values dc,dtheta,ds,dd");
  for (double d : a.damping)
    if (!(d > 0) || !std::isfinite(d)) throw usage_error("--damping values must be > 0");
  o.damping = {a.damping[0], a.damping[1], a.damping[2], a.damping[3]};
  if (a.move_tol < 0 || !std::isfinite(a.move_tol)) throw usage_error("--move-tol must be >= 0");
  o.move_tol = a.move_tol;
  if (a.max_iter < 0) throw usage_error("--max-iter must be >= 1");
  o.max_iter = a.max_iter > 0 ? a.max_iter : o.solver == feshape::Solver::equilibrium ? 200 : 200000;
  if (a.levels < 0 || a.levels > 20) throw usage_error("--levels must be in 0..20");
  o.levels = a.levels;
  if (!(a.tau > 0) || !std::isfinite(a.tau)) throw usage_error("--tau must be > 0");
  o.tau = a.tau;
  if (a.max_nodes < 6) throw usage_error("--max-nodes must be >= 6");
  o.max_nodes = static_cast<std::size_t>(a.max_nodes);
  if (a.reassign_every < 1) throw usage_error("--reassign-every must be >= 1");
  o.reassign_every = a.reassign_every;
  o.global_phase = !a.no_global_phase;
  o.threads = resolve_threads(a.threads);
  return o;
}

std::string level_path(const std::string& pattern, const std::string& name) {
  const auto at = pattern.find("%s");
  if (at == std::string::npos) throw usage_error("--levels-out {} has no %s for the level name", pattern);
  return pattern.substr(0, at) + name + pattern.substr(at + 2);
}

nlohmann::json model_json(const feshape::Model& m) {
  nlohmann::json j;
  j["center"] = {m.center.x(), m.center.y(), m.center.z()};
  j["quat"] = {m.rotation.w(), m.rotation.x(), m.rotation.y(), m.rotation.z()};
  nlohmann::json qs = nlohmann::json::object();
  for (int i = 0; i < feshape::n_global; ++i) qs[feshape::global_names()[i]] = m.qs[i];
  j["qs"] = qs;
  return j;
}

}  // namespace

int run_fit(const FitArgs& a) {
  feshape::FitOptions o = fit_options(a);
  const MeshTarget target = mesh_target(a.output, a.to);
  if (!a.levels_out.empty()) (void)level_path(a.levels_out, "G");
  if (!a.partial.empty()) (void)mesh_target(a.partial, a.to);
  const bool given = !a.model.qs.empty();
  if (a.init == InitRule::given && !given) throw usage_error("--init given needs --qs");
  feshape::Model model = model_from_args(a.model);  // usage errors before reading anything
  const std::vector<Eigen::Vector3d> points = read_points(a.input, a.in_format);
  if (!given) {
    feshape::auto_initialize(points, model);
    if (!a.model.center.empty()) model.center = Eigen::Vector3d(a.model.center[0], a.model.center[1], a.model.center[2]);
    if (!a.model.quat.empty()) model.rotation = Eigen::Quaterniond(a.model.quat[0], a.model.quat[1], a.model.quat[2], a.model.quat[3]).normalized();
  }
  if (o.move_tol == 0) {
    // The seed's 5e-5 for data a few units across: scale it with the data.
    Eigen::Vector3d lo = points[0], hi = points[0];
    for (const auto& p : points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    o.move_tol = 5e-5 * 0.5 * (hi - lo).norm();
  }
  std::vector<feshape::LevelResult> done;  // levels finished so far, for --partial
  std::vector<feshape::LevelResult> levels;
  Progress bar("feshape fit", 0, progress_wanted(a.progress));
  o.progress = bar.callback();
  try {
    levels = feshape::fit(points, model, o, [&](const feshape::LevelResult& l) {
      if (!a.partial.empty()) done.push_back(l);
    });
    bar.finish();
  } catch (const Error& e) {
    // A failure after some levels (the node limit, a breakdown): the last finished level
    // goes to --partial when asked, never to the output.
    if (e.status() == Status::failure && !a.partial.empty() && !done.empty()) {
      const MeshTarget t = mesh_target(a.partial, a.to);
      write_output(t.path, encode_model(done.back().model, t));
      throw Error(e.status(), fmt::format("{}; level {} written to {}", e.what(), done.back().name, a.partial));
    }
    throw;
  }
  for (const auto& l : levels)
    if (l.folded > 0)
      warn("feshape", fmt::format("level {}: {} of {} elements folded over; raise the membrane weights "
                                  "(--w w00,w01,w10,...: w01, w10)",
                                  l.name, l.folded, l.model.mesh.elements()));
  // Everything is known: write the levels, the final model, the report.
  if (!a.levels_out.empty())
    for (const auto& l : levels) {
      MeshTarget t = mesh_target(level_path(a.levels_out, l.name), a.to);
      write_output(t.path, encode_model(l.model, t));
    }
  if (!a.report.empty()) {
    nlohmann::json r = model_json(levels.back().model);
    r["points"] = points.size();
    r["stiffness"] = {{"w00", o.weights.w00}, {"w01", o.weights.w01}, {"w10", o.weights.w10},
                      {"w02", o.weights.w02}, {"w11", o.weights.w11}, {"w20", o.weights.w20}};
    r["beta"] = o.beta;
    r["solver"] = a.solver;
    r["tau"] = o.tau;
    r["move_tol"] = o.move_tol;
    r["levels"] = nlohmann::json::array();
    for (const auto& l : levels) {
      nlohmann::json j = model_json(l.model);
      j["name"] = l.name;
      j["nodes"] = l.model.mesh.nodes();
      j["elements"] = l.model.mesh.elements();
      j["selected"] = l.selected;
      j["iterations"] = l.iterations;
      j["converged"] = l.converged;
      j["mean"] = l.error.mean;
      j["max"] = l.error.max;
      j["std"] = l.error.std;
      j["var"] = l.error.var;
      j["folded"] = l.folded;
      if (l.surface_rms >= 0) j["surface_rms"] = l.surface_rms;
      j["time_s"] = l.time_s;
      r["levels"].push_back(j);
    }
    write_output(a.report, r.dump(2) + "\n");
  }
  write_output(target.path, encode_model(levels.back().model, target));
  return 0;
}

}  // namespace fest::feshape_tool
