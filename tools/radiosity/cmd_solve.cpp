// radiosity solve: read a scene, mesh it, shoot to the tolerance (with adaptive rounds),
// and write the lit meshes, the shot log, the report and a picture.

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "formats/table/table_io.hpp"
#include "lit_output.hpp"
#include "radiosity/direct.hpp"
#include "radiosity/solver.hpp"
#include "radiosity/vertex_values.hpp"
#include "scene_input.hpp"
#include "view.hpp"

namespace fest::radiosity_tool {
namespace {


nlohmann::json rgb(const radiosity::Rgb& c) { return {c[0], c[1], c[2]}; }

std::string safe_name(const std::string& name) {
  std::string out;
  for (char ch : name) out += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_') ? ch : '_';
  return out.empty() ? "object" : out;
}

}  // namespace

namespace {

void check_args(const SolveArgs& args) {
  if ((args.ff == radiosity::Engine::hemicube || args.ff == radiosity::Engine::hybrid) &&
      (args.hemicube_res < 2 || args.hemicube_res % 2 != 0))
    throw usage_error("--hemicube-res must be even and at least 2");
  if (args.omega >= 0 && args.solver == radiosity::Solver::sor && !(args.omega >= 1 && args.omega < 2))
    throw usage_error("--omega for sor must lie in [1, 2)");
}

radiosity::Model mesh_scene(const SolveArgs& args, const radiosity::Scene& scene) {
  radiosity::MeshingOptions mo;
  mo.patch_size = args.patch_size;
  mo.element_size = args.element_size;
  mo.no_mesh = args.no_mesh;
  mo.emission_is_radiance = args.emission_is_radiance;
  return radiosity::build_model(scene, mo);
}

radiosity::FormFactorOptions form_factor_options(const SolveArgs& args, int threads) {
  radiosity::FormFactorOptions fo;
  fo.engine = args.ff;
  fo.hemicube_res = args.hemicube_res;
  fo.samples = args.samples;
  fo.threads = threads;
  return fo;
}

radiosity::SolveOptions solve_options(const SolveArgs& args, int threads) {
  radiosity::SolveOptions so;
  so.solver = args.solver;
  so.omega = args.omega;
  so.tol = args.tol;
  so.max_shots = args.max_shots;
  so.levels = args.direct ? 0 : args.levels;
  so.grad = args.grad;
  so.min_element = args.min_element;
  so.threads = threads;
  return so;
}

// The --log columns, one row per shot, gathered while the solver runs.
struct ShotLog {
  std::vector<double> shot, patch, object, unshot, omega, seconds, level;

  void add(const radiosity::ShotRecord& r) {
    shot.push_back(static_cast<double>(r.shot));
    patch.push_back(r.patch);
    object.push_back(r.object);
    unshot.push_back(r.unshot_fraction);
    omega.push_back(r.omega);
    seconds.push_back(r.seconds);
    level.push_back(r.level);
  }

  std::string csv() const {
    Table log;
    log.add_column("shot", shot);
    log.add_column("patch", patch);
    log.add_column("object", object);
    log.add_column("unshot_fraction", unshot);
    log.add_column("omega", omega);
    log.add_column("seconds", seconds);
    log.add_column("level", level);
    return formats::write_table(log, formats::Format::csv);
  }
};

void warn_about_convergence(const SolveArgs& args, const radiosity::SolveStats& stats) {
  if (stats.fell_back && !args.quiet)
    warn("radiosity", "the unshot total grew for 50 shots in a row: switched to plain progressive refinement");
  if (stats.converged) return;
  if (args.strict)
    throw runtime_failure("no convergence after {} shots (unshot fraction {:.3g} > tol {})", stats.shots,
                          stats.unshot_fraction, args.tol);
  if (!args.quiet)
    warn("radiosity", fmt::format("stopped after {} shots at unshot fraction {:.3g} (tol {}); raise --max-shots",
                                  stats.shots, stats.unshot_fraction, args.tol));
}

// The picture of --view: vertex radiances B/pi over the elements' fans, tone-mapped.
std::string view_png(const radiosity::Model& model, const radiosity::VertexValues& vv, const CameraArgs& camera,
                     double exposure, int threads) {
  ViewMesh vm;
  vm.positions = vv.position;
  for (const auto& b : vv.B) vm.values.emplace_back(b[0] / M_PI, b[1] / M_PI, b[2] / M_PI);
  for (std::size_t k = 0; k < vv.elements.size(); ++k) {
    const auto& c = vv.element_corners[k];
    const int n = model.elements[vv.elements[k]].poly.n;
    for (int j = 1; j + 1 < n; ++j)
      vm.triangles.push_back({static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[j]),
                              static_cast<std::uint32_t>(c[j + 1])});
  }
  return formats::write_image(to_display(render_values(vm, camera, threads), exposure, 1 / 2.2), formats::Format::png);
}

// --direct: the largest difference between the shooting and the direct solution, relative
// to the direct value with a floor of 1e-3 of the brightest element.
double direct_max_rel_diff(const radiosity::Model& model, const std::vector<radiosity::Rgb>& direct_b) {
  double worst = 0, bmax = 0;
  for (const auto& b : direct_b) bmax = std::max(bmax, b.maxCoeff());
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(model.elements[e].B[c] - direct_b[e][c]) / std::max(direct_b[e][c], 1e-3 * bmax));
  return worst;
}

// Timings of the run, for the report.
struct SolveTimes {
  SteadyClock::time_point start;
  double read_s = 0, output_s = 0;
};

nlohmann::json solve_report(const SolveArgs& args, const radiosity::Scene& scene, const radiosity::SceneCheck& check,
                            const radiosity::Model& model, const radiosity::FormFactors& ff,
                            const radiosity::SolveStats& stats, const radiosity::VertexValues& vv, double exposure,
                            int threads, const SolveTimes& times) {
  const radiosity::RadiosityRange range = radiosity::radiosity_range(model);
  double emitted = 0, absorbed = 0;
  for (const radiosity::Element& el : model.elements) {
    if (!el.active) continue;
    const radiosity::Patch& p = model.patches[el.patch];
    emitted += el.area * p.E.sum();
    absorbed += el.area * ((1 - p.rho) * el.H).sum();
  }
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& o : model.objects) objects.push_back(o.name);
  const double total = seconds_since(times.start);
  nlohmann::json report = {
      {"tool", "radiosity"},
      {"scene", {{"objects", objects}, {"faces", check.faces}, {"open_edges", check.open_edges},
                 {"closed", check.open_edges == 0}, {"units", scene.units}, {"diagonal", check.diagonal}}},
      {"ff", radiosity::engine_name(args.ff)},
      {"solver", radiosity::solver_name(args.solver)},
      {"omega", args.omega >= 0 ? args.omega : (args.solver == radiosity::Solver::sor ? 1.5 : 1.0)},
      {"tol", args.tol},
      {"threads", threads},
      {"patches", model.patches.size()},
      {"elements", model.active_elements().size()},
      {"elements_per_level", stats.elements_per_level},
      {"shots", stats.shots},
      {"shots_per_level", stats.shots_per_level},
      {"converged", stats.converged},
      {"fell_back_to_pr", stats.fell_back},
      {"unshot_fraction", stats.unshot_fraction},
      {"radiosity", {{"min", rgb(range.min)}, {"max", rgb(range.max)}, {"mean", rgb(range.mean)}}},
      {"energy", {{"emitted", emitted}, {"absorbed", absorbed},
                  {"relative_imbalance", emitted > 0 ? (emitted - absorbed) / emitted : 0.0}}},
      {"exposure", exposure},
      {"vertices", vv.position.size()},
      {"time", {{"total_s", total}, {"read_and_mesh_s", times.read_s}, {"visibility_s", stats.visibility_seconds},
                {"solve_s", stats.solve_seconds}, {"subdivision_s", stats.subdivision_seconds},
                {"output_s", times.output_s},
                {"visibility_fraction", total > 0 ? stats.visibility_seconds / total : 0.0}}},
  };
  if (ff.hemicube()) {
    report["hemicube_res"] = args.hemicube_res;
    report["hemicube_raw_sum"] = ff.hemicube()->raw_sum();
  } else {
    report["samples"] = args.samples;
  }
  return report;
}

}  // namespace

int run_solve(const SolveArgs& args, const CameraArgs& camera) {
  SolveTimes times;
  times.start = SteadyClock::now();
  const int threads = resolve_threads(args.threads);
  check_args(args);

  const auto t_read = SteadyClock::now();
  const radiosity::Scene scene = read_scene(args.scene);
  const radiosity::SceneCheck check = radiosity::check_scene(scene);
  radiosity::Model model = mesh_scene(args, scene);
  times.read_s = seconds_since(t_read);
  if (check.open_edges > 0 && !args.quiet)
    warn("radiosity", fmt::format("the scene is open: {} edge(s) belong to one face only; light escapes through the gaps",
                                  check.open_edges));

  radiosity::FormFactors ff(model, form_factor_options(args, threads));
  std::vector<radiosity::Rgb> direct_b;
  if (args.direct) {
    if (args.levels > 0 && !args.quiet) warn("radiosity", "--direct compares level 0 only; adaptive rounds skipped");
    direct_b = radiosity::direct_solve(model, ff);
  }

  radiosity::SolveOptions so = solve_options(args, threads);
  ShotLog log;
  // --progress: each level's unshot fraction from 1 down to --tol on a log scale, 1000
  // steps per level (a solve stopped by --max-shots ends short of its level's end).
  Progress bar("radiosity solve", 1000 * static_cast<std::uint64_t>(so.levels + 1),
               progress_wanted(args.progress));
  so.on_shot = [&](const radiosity::ShotRecord& r, const radiosity::Model&) {
    if (!args.log.empty()) log.add(r);
    const double part = r.unshot_fraction > 0 && args.tol < 1 ? std::log(std::min(1.0, r.unshot_fraction)) / std::log(args.tol) : 1.0;
    bar.set(1000 * static_cast<std::uint64_t>(r.level) + static_cast<std::uint64_t>(1000 * std::clamp(part, 0.0, 1.0)));
  };
  const radiosity::SolveStats stats = radiosity::solve(model, ff, so);
  bar.finish();
  warn_about_convergence(args, stats);

  const auto t_out = SteadyClock::now();
  const radiosity::VertexValues vv = radiosity::vertex_values(model, args.crease);
  double exposure = 0;
  const auto colours =
      radiosity::display_colours(vv.B, args.exposure, &exposure, radiosity::reflector_vertices(model, vv));
  const std::string ply = lit_ply(model, vv, colours);
  std::vector<std::pair<std::string, std::string>> split;
  if (!args.split_objects.empty())
    for (std::size_t o = 0; o < model.objects.size(); ++o)
      split.emplace_back(fmt::format("{:03d}_{}.ply", o, safe_name(model.objects[o].name)),
                         lit_ply(model, vv, colours, static_cast<int>(o)));
  const std::string png = args.view.empty() ? std::string() : view_png(model, vv, camera, exposure, threads);
  const std::string csv = args.log.empty() ? std::string() : log.csv();
  times.output_s = seconds_since(t_out);

  nlohmann::json report;
  if (!args.report.empty()) {
    report = solve_report(args, scene, check, model, ff, stats, vv, exposure, threads, times);
    if (args.direct) report["direct"] = {{"max_rel_diff", direct_max_rel_diff(model, direct_b)}, {"floor", "1e-3 x max B"}};
  } else if (args.direct && !args.quiet) {
    std::fprintf(stderr, "radiosity: direct solve: max relative difference %.3g\n", direct_max_rel_diff(model, direct_b));
  }

  // Everything is known to be good: write.
  if (!split.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.split_objects, ec);
    if (ec) throw io_error("cannot create the folder {}: {}", args.split_objects, ec.message());
    for (const auto& [name, bytes] : split) write_output((std::filesystem::path(args.split_objects) / name).string(), bytes);
  }
  if (!csv.empty()) write_output(args.log, csv);
  if (!png.empty()) write_output(args.view, png);
  if (!args.report.empty()) write_output(args.report, report.dump(2) + "\n");
  if (args.split_objects.empty() || args.output != "-") write_output(args.output, ply);
  return 0;
}

}  // namespace fest::radiosity_tool
