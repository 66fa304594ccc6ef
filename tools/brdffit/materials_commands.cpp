// brdffit fit / cluster / project / normals: flags -> formats -> lib/brdffit -> formats.

#include "materials_commands.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "brdffit/brdf_json.hpp"
#include "brdffit/cluster.hpp"
#include "brdffit/lafortune_fit.hpp"
#include "brdffit/ltw_format.hpp"
#include "brdffit/ltx_format.hpp"
#include "brdffit/merl.hpp"
#include "brdffit/normals.hpp"
#include "brdffit/project.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/brdf/merl_io.hpp"
#include "formats/table/table_io.hpp"

namespace brdffit_tool {

namespace {

using namespace fest;
using namespace fest::brdffit;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Options every fit-based subcommand shares.
struct FitFlags {
  int lobes = 1;
  bool shared = false;
  double max_lobe_albedo = 1.0;
  int starts = 4;
  std::string robust = "none";
  std::size_t subsample = 200000;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string report;
};

struct FitArgs {
  FitFlags fit;
  std::string input = "-", merl, output = "-";
  bool angles = false;
};
struct ClusterArgs {
  FitFlags fit;
  std::string input = "-", output = "-", clusters = "5";
  ClusterOptions c;
  int min_samples = 2;
};
struct ProjectArgs {
  std::string input = "-", output = "-", clusters_file, weights = "scalar";
  int basis = 4;
  bool nonneg = false;
  double split_scale = 1.0;
  int split_iters = 10, threads = 0, min_samples = 2;
  std::string report;
};
struct NormalsArgs {
  std::string input = "-", output = "-", svbrdf;
  NormalOptions n;
  int threads = 0;
  bool ascii = false;
  std::string report;
};

FitArgs fit_args;
ClusterArgs cluster_args;
ProjectArgs project_args;
NormalsArgs normals_args;

void add_fit_flags(CLI::App* s, FitFlags& f) {
  s->add_option("--lobes", f.lobes, "Lafortune lobes K (1..3)")->default_val(1);
  s->add_flag("--shared-lobe", f.shared, "Share Cxy and N across channels (Cz = 1, per-channel scale)");
  s->add_option("--max-lobe-albedo", f.max_lobe_albedo,
                "Bound of every lobe's directional albedo (1 = energy conserving; 0 = none)")
      ->default_val(1.0);
  s->add_option("--starts", f.starts, "Multi-start: N in {5, 20, 80, 300}, the first STARTS")->default_val(4);
  s->add_option("--robust", f.robust, "Loss: none or huber:DELTA")->default_val("none");
  s->add_option("--fit-subsample", f.subsample, "Fit on at most this many samples (0 = all)")->default_val(200000);
  s->add_option("--seed", f.seed, "Seed of every random choice")->default_val(1);
  s->add_option("--report", f.report, "Write timings, counts and errors as JSON");
  s->add_option("--threads", f.threads, "Worker threads (0 = all cores)")->default_val(0);
}

FitOptions fit_options(const FitFlags& f) {
  FitOptions o;
  o.model.lobes = f.lobes;
  o.model.shared = f.shared;
  if (!(f.max_lobe_albedo >= 0)) throw usage_error("--max-lobe-albedo must be >= 0, not {}", f.max_lobe_albedo);
  o.model.max_lobe_albedo = f.max_lobe_albedo;
  parameter_count(o.model);  // validates --lobes
  o.starts = f.starts;
  if (f.starts < 1 || f.starts > 4) throw usage_error("--starts must be 1..4, not {}", f.starts);
  if (f.robust.rfind("huber:", 0) == 0) {
    char* end = nullptr;
    o.huber_delta = std::strtod(f.robust.c_str() + 6, &end);
    if (*end != '\0' || !(o.huber_delta > 0)) throw usage_error("--robust huber:DELTA needs a positive DELTA, not '{}'", f.robust);
  } else if (f.robust != "none") {
    throw usage_error("--robust must be none or huber:DELTA, not '{}'", f.robust);
  }
  o.subsample = f.subsample;
  o.seed = f.seed;
  o.threads = resolve_threads(f.threads);
  return o;
}

void write_report(const std::string& path, const nlohmann::json& j) {
  if (!path.empty()) write_output(path, formats::write_json(j));
}

// Binary products go to a terminal only by mistake (spec §4).
void refuse_binary_terminal(const std::string& output) {
  if (is_stdio(output) && isatty(STDOUT_FILENO)) throw usage_error("refusing to write binary to a terminal (use -o or a pipe)");
}

LumitexelSet load_lumitexels(const std::string& path, nlohmann::json* header) {
  const std::string bytes = read_input(path);
  try {
    return decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), header);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), is_stdio(path) ? "standard input" : path));
  }
}

// Lumitexels with fewer than min_samples samples take no part (their count is set to 0
// in the copy used); refuses a set where none is left.
std::size_t drop_sparse(LumitexelSet& set, int min_samples) {
  if (min_samples < 1) throw usage_error("--min-samples must be at least 1");
  std::size_t kept = 0;
  for (Lumitexel& l : set.lumitexels) {
    if (l.count < min_samples) l.count = 0;
    else ++kept;
  }
  if (kept == 0) throw bad_input("no lumitexel has >= {} samples", min_samples);
  return kept;
}

// ---- fit ----------------------------------------------------------------------------

std::vector<FitSample> samples_from_table(const Table& t, bool angles, const std::string& where) {
  const std::vector<std::string> names = angles ? std::vector<std::string>{"theta_i", "phi_i", "theta_o", "phi_o", "r", "g", "b"}
                                                : std::vector<std::string>{"ux", "uy", "uz", "vx", "vy", "vz", "r", "g", "b"};
  std::vector<const std::vector<double>*> col;
  for (const std::string& n : names) {
    const std::size_t k = t.find(n);
    if (k == Table::npos) throw bad_input("samples table has no column '{}' ({})", n, where);
    col.push_back(&t.columns[k]);
  }
  std::vector<FitSample> out;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    auto v = [&](std::size_t c) { return (*col[c])[i]; };
    Eigen::Vector3d u, w, r;
    if (angles) {
      u = {std::sin(v(0)) * std::cos(v(1)), std::sin(v(0)) * std::sin(v(1)), std::cos(v(0))};
      w = {std::sin(v(2)) * std::cos(v(3)), std::sin(v(2)) * std::sin(v(3)), std::cos(v(2))};
      r = {v(4), v(5), v(6)};
    } else {
      u = {v(0), v(1), v(2)};
      w = {v(3), v(4), v(5)};
      r = {v(6), v(7), v(8)};
    }
    if (!u.allFinite() || !w.allFinite() || !r.allFinite())
      throw bad_input("samples table line {}: not a finite number ({})", i + 2, where);
    if (u.norm() == 0 || w.norm() == 0) throw bad_input("samples table line {}: zero direction ({})", i + 2, where);
    out.push_back(make_fit_sample(u.normalized(), w.normalized(), r));
  }
  if (out.empty()) throw bad_input("samples table has no rows ({})", where);
  return out;
}

int run_fit(const FitArgs& a) {
  const auto t0 = Clock::now();
  const FitOptions o = fit_options(a.fit);
  std::vector<FitSample> samples;
  std::string source;
  if (!a.merl.empty()) {
    source = a.merl;
    try {
      samples = merl_samples(MerlTable{formats::read_merl(read_input(a.merl)).values});
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), a.merl));
    }
  } else {
    source = is_stdio(a.input) ? "standard input" : a.input;
    const std::string bytes = read_input(a.input);
    Table t;
    try {
      t = formats::read_table(bytes, bytes.find('\t') != std::string::npos && bytes.find(',') == std::string::npos
                                         ? formats::Format::tsv
                                         : formats::Format::csv);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), source));
    }
    samples = samples_from_table(t, a.angles, source);
  }
  FitOptions in_data_units = o;
  in_data_units.model.max_lobe_albedo = albedo_bound_in_data_units(o.model.max_lobe_albedo, samples);
  const FitResult r = fit_brdf(samples, in_data_units);
  nlohmann::json out = brdf_to_json(r.brdf);
  if (o.model.shared) out["shared_lobe"] = true;
  const double rms = std::sqrt(r.mean_squared);
  out["fit"] = {{"samples", samples.size()}, {"samples_fitted", r.samples_used}, {"rms_residual", rms},
                {"iterations", r.iterations}, {"energy", r.energy}};
  write_output(a.output, formats::write_json(out));
  write_report(a.fit.report, {{"command", "fit"}, {"source", source}, {"samples", samples.size()},
                              {"samples_fitted", r.samples_used}, {"rms_residual", rms}, {"sigma2", r.sigma2},
                              {"iterations", r.iterations}, {"seconds", seconds_since(t0)}});
  return 0;
}

// ---- cluster ------------------------------------------------------------------------

int run_cluster(ClusterArgs a) {
  const auto t0 = Clock::now();
  ClusterOptions o = a.c;
  o.fit = fit_options(a.fit);
  if (a.clusters == "auto") {
    o.clusters = 0;
  } else {
    char* end = nullptr;
    const long k = std::strtol(a.clusters.c_str(), &end, 10);
    if (*end != '\0' || k < 1 || k > 65535) throw usage_error("--clusters must be 1..65535 or auto, not '{}'", a.clusters);
    o.clusters = static_cast<int>(k);
  }
  nlohmann::json header;
  LumitexelSet set = load_lumitexels(a.input, &header);
  const std::size_t kept = drop_sparse(set, a.min_samples);
  const auto t_read = Clock::now();
  const std::vector<FitSample> local = local_samples(set, o.fit.threads);
  const ClusterResult r = cluster_lumitexels(set, local, o);
  nlohmann::json out = clusters_to_json(r);
  out["lumitexels"] = set.lumitexels.size();
  out["lumitexels_clustered"] = kept;
  out["mesh_sha256"] = set.mesh_sha256;
  out["options"] = {{"clusters", a.clusters}, {"split_scale", o.split_scale}, {"split_iters", o.split_iters},
                    {"stable", o.stable}, {"global_iters", o.global_iters}, {"min_cluster", o.min_cluster},
                    {"min_gain", o.min_gain}, {"fit_subsample", o.fit.subsample}, {"seed", o.fit.seed},
                    {"min_samples", a.min_samples}};
  write_output(a.output, formats::write_json(out));
  write_report(a.fit.report, {{"command", "cluster"}, {"lumitexels", set.lumitexels.size()}, {"clustered", kept},
                              {"samples", set.samples.size()}, {"clusters", r.clusters.size()},
                              {"total_error", r.total_error}, {"seconds_read", std::chrono::duration<double>(t_read - t0).count()},
                              {"seconds", seconds_since(t0)}});
  return 0;
}

// ---- project ------------------------------------------------------------------------

int run_project(const ProjectArgs& a) {
  const auto t0 = Clock::now();
  refuse_binary_terminal(a.output);
  ProjectOptions o;
  o.basis = a.basis;
  if (a.weights != "scalar" && a.weights != "rgb") throw usage_error("--weights must be scalar or rgb, not '{}'", a.weights);
  o.weights = a.weights == "rgb" ? WeightMode::rgb : WeightMode::scalar;
  o.nonneg = a.nonneg;
  o.split.split_scale = a.split_scale;
  o.split.split_iters = a.split_iters;
  o.split.fit.threads = resolve_threads(a.threads);
  if (!(a.split_scale > 0) || a.split_iters < 1) throw usage_error("--split-scale must be positive and --split-iters >= 1");
  ClusterResult clusters;
  try {
    clusters = clusters_from_json(formats::read_json(read_input(a.clusters_file)));
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), a.clusters_file));
  }
  o.split.fit.model = clusters.model;
  nlohmann::json header;
  LumitexelSet set = load_lumitexels(a.input, &header);
  drop_sparse(set, a.min_samples);
  const std::vector<FitSample> local = local_samples(set, o.split.fit.threads);
  const Projection p = project_lumitexels(set, local, clusters.model, clusters.clusters, o);
  const ProjectionError err = projection_error(set, local, p, o.split.fit.threads);
  const std::string bytes = encode_ltw(p, {{"mesh_sha256", set.mesh_sha256},
                                            {"error", {{"projected", err.projected}, {"per_cluster", err.per_cluster}}}});
  write_output(a.output, bytes);
  write_report(a.report, {{"command", "project"}, {"lumitexels", set.lumitexels.size()}, {"basis_size", p.basis_size},
                          {"basis_brdfs", p.basis.brdfs.size()}, {"error_projected", err.projected},
                          {"error_per_cluster", err.per_cluster}, {"seconds", seconds_since(t0)}});
  return 0;
}

// ---- normals ------------------------------------------------------------------------

// normals.ply (spec §3): a point cloud with x y z nx ny nz (refined) and nx0 ny0 nz0
// (mesh). fest's mesh writer keeps only the standard vertex attributes, so this small
// fixed-layout PLY is written here.
std::string normals_ply(const LumitexelSet& set, const NormalResult& r, bool ascii) {
  std::string out = "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment brdffit normals: refined (nx ny nz) and mesh (nx0 ny0 nz0) normals\n";
  out += "element vertex " + std::to_string(set.lumitexels.size()) + "\n";
  for (const char* n : {"x", "y", "z", "nx", "ny", "nz", "nx0", "ny0", "nz0"}) out += std::string("property float ") + n + "\n";
  out += "property uchar refined\nend_header\n";
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i) {
    const Lumitexel& l = set.lumitexels[i];
    const float v[9] = {l.p.x(), l.p.y(), l.p.z(), r.normals[i].x(), r.normals[i].y(), r.normals[i].z(),
                        l.n.x(), l.n.y(), l.n.z()};
    if (ascii) {
      char line[256];
      int len = 0;
      for (float f : v) len += std::snprintf(line + len, sizeof(line) - static_cast<std::size_t>(len), "%.9g ", static_cast<double>(f));
      out.append(line, static_cast<std::size_t>(len));
      out += std::to_string(r.refined[i]) + "\n";
    } else {
      out.append(reinterpret_cast<const char*>(v), sizeof(v));
      out.push_back(static_cast<char>(r.refined[i]));
    }
  }
  return out;
}

int run_normals(const NormalsArgs& a) {
  const auto t0 = Clock::now();
  if (!a.ascii) refuse_binary_terminal(a.output);
  NormalOptions o = a.n;
  o.threads = resolve_threads(a.threads);
  Projection p;
  nlohmann::json wh;
  try {
    p = decode_ltw(read_input(a.svbrdf), &wh);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), a.svbrdf));
  }
  nlohmann::json header;
  const LumitexelSet set = load_lumitexels(a.input, &header);
  if (wh.contains("mesh_sha256") && wh["mesh_sha256"].is_string() && wh["mesh_sha256"] != set.mesh_sha256)
    throw bad_input("the weights were made for another mesh (mesh_sha256 differs) ({})", a.svbrdf);
  if (p.cluster.size() != set.lumitexels.size())
    throw bad_input("{} has weights for {} lumitexels, the lumitexel file has {}", a.svbrdf, p.cluster.size(), set.lumitexels.size());
  const NormalResult r = refine_normals(set, p, o);
  write_output(a.output, normals_ply(set, r, a.ascii));
  write_report(a.report, {{"command", "normals"}, {"lumitexels", set.lumitexels.size()}, {"refined", r.refined_count},
                          {"residual_before", r.residual_before}, {"residual_after", r.residual_after},
                          {"seconds", seconds_since(t0)}});
  return 0;
}

}  // namespace

void add_materials_commands(CLI::App& app) {
  auto* f = app.add_subcommand("fit", "Fit one Lafortune BRDF to samples (CSV) or a MERL .binary; brdf.json to stdout");
  f->add_option("input", fit_args.input, "samples.csv: ux,uy,uz,vx,vy,vz,r,g,b (local frame; r = f u_z), - = stdin")->default_val("-");
  f->add_option("--merl", fit_args.merl, "Fit a MERL .binary BRDF table instead");
  f->add_flag("--angles", fit_args.angles, "Columns theta_i,phi_i,theta_o,phi_o,r,g,b (radians)");
  f->add_option("-o,--output", fit_args.output, "brdf.json (- = stdout)")->default_val("-");
  add_fit_flags(f, fit_args.fit);

  auto* c = app.add_subcommand("cluster", "Cluster lumitexels into materials by split and refit; clusters.json to stdout");
  c->add_option("input", cluster_args.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  c->add_option("-o,--output", cluster_args.output, "clusters.json (- = stdout)")->default_val("-");
  c->add_option("--clusters", cluster_args.clusters, "Number of materials, or auto (split until --min-gain)")->default_val("5");
  c->add_option("--split-scale", cluster_args.c.split_scale, "kappa: split step in standard deviations")->default_val(1.0);
  c->add_option("--split-iters", cluster_args.c.split_iters, "Refits per split at most")->default_val(10);
  c->add_option("--stable", cluster_args.c.stable, "A split ends when fewer members change side")->default_val(0.005);
  c->add_option("--global-iters", cluster_args.c.global_iters, "Global reassignment rounds per split")->default_val(3);
  c->add_option("--min-cluster", cluster_args.c.min_cluster, "Dissolve clusters below this fraction of lumitexels")->default_val(0.001);
  c->add_option("--min-gain", cluster_args.c.min_gain, "auto: stop when a split gains less (fraction of the 1-cluster error)")->default_val(0.02);
  c->add_option("--min-samples", cluster_args.min_samples, "Ignore lumitexels with fewer samples")->default_val(2);
  add_fit_flags(c, cluster_args.fit);

  auto* p = app.add_subcommand("project", "Per-lumitexel weights over per-cluster basis BRDFs; .ltw to stdout");
  p->add_option("input", project_args.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  p->add_option("--clusters", project_args.clusters_file, "clusters.json from brdffit cluster")->required();
  p->add_option("-o,--output", project_args.output, ".ltw output (- = stdout)")->default_val("-");
  p->add_option("--basis", project_args.basis, "Basis BRDFs per cluster")->default_val(4);
  p->add_option("--weights", project_args.weights, "scalar (one per basis BRDF) or rgb (per channel)")->default_val("scalar");
  p->add_flag("--nonneg", project_args.nonneg, "Non-negative weights (NNLS) instead of the SVD solution");
  p->add_option("--split-scale", project_args.split_scale, "kappa of the trial split")->default_val(1.0);
  p->add_option("--split-iters", project_args.split_iters, "Refits of the trial split at most")->default_val(10);
  p->add_option("--min-samples", project_args.min_samples, "Lumitexels with fewer samples get the pure cluster BRDF")->default_val(2);
  p->add_option("--report", project_args.report, "Write timings and errors as JSON");
  p->add_option("--threads", project_args.threads, "Worker threads (0 = all cores)")->default_val(0);

  auto* n = app.add_subcommand("normals", "Refine normals against the projected BRDFs; normals.ply to stdout");
  n->add_option("input", normals_args.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  n->add_option("--svbrdf", normals_args.svbrdf, ".ltw from brdffit project")->required();
  n->add_option("-o,--output", normals_args.output, "normals.ply (- = stdout)")->default_val("-");
  n->add_option("--normal-min-samples", normals_args.n.min_samples, "Refine lumitexels with at least this many samples")->default_val(5);
  n->add_option("--max-tilt", normals_args.n.max_tilt_deg, "Largest tilt from the mesh normal (degrees)")->default_val(30);
  n->add_option("--alternate", normals_args.n.alternate, "Rounds of (re-projection, normals)")->default_val(1);
  n->add_flag("--ascii", normals_args.ascii, "ASCII PLY instead of binary");
  n->add_option("--report", normals_args.report, "Write timings and residuals as JSON");
  n->add_option("--threads", normals_args.threads, "Worker threads (0 = all cores)")->default_val(0);
}

int run_materials_command(const CLI::App& app) {
  if (app.got_subcommand("fit")) return run_fit(fit_args);
  if (app.got_subcommand("cluster")) return run_cluster(cluster_args);
  if (app.got_subcommand("project")) return run_project(project_args);
  if (app.got_subcommand("normals")) return run_normals(normals_args);
  return -1;
}

}  // namespace brdffit_tool
