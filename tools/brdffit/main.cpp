// brdffit: spatially varying BRDFs from a few registered HDR photographs of a scanned
// object (docs/brdffit.md; Lensch et al., chapter 8 of the Festschrift). One executable,
// one subcommand per stage. Flags only: they fill the typed options of commands.hpp, and
// the subcommand given runs inside run_tool, so errors become one line and the exit
// status of README's "Conventions".

#include <cstdlib>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

using namespace fest::brdffit_tool;

// --materials N (built-in materials) or a materials JSON.
void set_materials(SynthArgs& a, const std::string& text) {
  const bool numeric = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  a.material_count = numeric ? std::stoi(text) : a.material_count;
  a.materials_file = numeric ? std::string() : text;
}

// --robust none or huber:DELTA -> the Huber threshold (0 = none).
double huber_delta(const std::string& text) {
  if (text.rfind("huber:", 0) == 0) {
    char* end = nullptr;
    const double delta = std::strtod(text.c_str() + 6, &end);
    if (*end != '\0' || !(delta > 0)) throw fest::usage_error("--robust huber:DELTA needs a positive DELTA, not '{}'", text);
    return delta;
  }
  if (text != "none") throw fest::usage_error("--robust must be none or huber:DELTA, not '{}'", text);
  return 0;
}

// --clusters N or auto (0).
int cluster_count(const std::string& text) {
  if (text == "auto") return 0;
  char* end = nullptr;
  const long k = std::strtol(text.c_str(), &end, 10);
  if (*end != '\0' || k < 1 || k > 65535) throw fest::usage_error("--clusters must be 1..65535 or auto, not '{}'", text);
  return static_cast<int>(k);
}

void add_fit_flags(CLI::App* s, FitFlags& f) {
  s->add_option("--lobes", f.lobes, "Lafortune lobes K (1..3)")->default_val(1)->check(fest::cli::range(1, 3));
  s->add_flag("--shared-lobe", f.shared, "Share Cxy and N across channels (Cz = 1, per-channel scale)");
  s->add_option("--max-lobe-albedo", f.max_lobe_albedo,
                "Bound of every lobe's directional albedo (1 = energy conserving; 0 = none)")
      ->default_val(1.0);
  s->add_option("--starts", f.starts, "Multi-start: N in {5, 20, 80, 300}, the first STARTS")->default_val(4)->check(fest::cli::range(1, 4));
  s->add_option_function<std::string>(
       "--robust", [&f](const std::string& text) { f.huber_delta = huber_delta(text); }, "Loss: none or huber:DELTA")
      ->default_str("none");
  s->add_option("--fit-subsample", f.subsample, "Fit on at most this many samples (0 = all)")->default_val(200000);
  s->add_option("--seed", f.seed, "Seed of every random choice")->default_val(1);
  s->add_option("--report", f.report, "Write timings, counts and errors as JSON");
  fest::cli::add_threads(*s, f.threads);
}

CLI::App* add_synth(CLI::App& app, SynthArgs& synth) {
  namespace cli = fest::cli;
  auto* s = app.add_subcommand("synth", "Synthetic ground truth: a mesh with known materials on a turntable, HDR images, "
                                        "masks, rig.json, truth.json");
  s->add_option("--mesh", synth.mesh, "Mesh (PLY/OBJ/OFF/STL); default: an icosphere");
  s->add_option("--sphere", synth.sphere_level, "Icosphere subdivision level when no --mesh (20*4^L triangles)")
      ->check(fest::cli::range(0, 9));
  s->add_option("--radius", synth.sphere_radius, "Icosphere radius")->check(fest::cli::positive);
  s->add_option_function<std::string>(
      "--materials", [&synth](const std::string& text) { set_materials(synth, text); },
      "Number of built-in materials on surface patches, or a materials JSON");
  s->add_option("--views", synth.setup.views, "Turntable angles")->check(fest::cli::range(1, 4096));
  s->add_option("--lights", synth.setup.lights, "Point lights (one image per view and light)")->check(fest::cli::range(1, 64));
  s->add_option("--width", synth.setup.width, "Image width")->check(fest::cli::range(8, 65536));
  s->add_option("--height", synth.setup.height, "Image height")->check(fest::cli::range(8, 65536));
  s->add_option("--elevation", synth.setup.elevation_deg, "Camera elevation above the table, degrees")
      ->check(fest::cli::range(-89.0, 89.0));
  s->add_option("--distance", synth.setup.distance, "Camera distance in bounding-sphere radii")
      ->check(fest::cli::range(1.1, 1000.0));
  s->add_option("--fill", synth.setup.fill, "Fraction of the shorter image side the bounding sphere spans")
      ->check(fest::cli::range(0.01, 1.0));
  s->add_option("--noise", synth.noise, "Multiplicative Gaussian noise, relative standard deviation")
      ->check(fest::cli::range(0.0, 1.0));
  s->add_option("--seed", synth.seed, "Seed of every random choice (patches, noise, normal perturbation)");
  s->add_option("--env", synth.env, "Lat-long HDR environment map (EXR) seen as the background");
  s->add_option("--env-light", synth.env_light, "Also light the object diffusely by the environment, scaled")
      ->check(fest::cli::non_negative);
  s->add_option("--perturb-normals", synth.perturb_deg, "Tilt the written mesh's normals by up to DEG (truth kept)")
      ->check(fest::cli::range(0.0, 60.0));
  s->add_option("--shadow-res", synth.shadow_res, "Shadow map size")->check(fest::cli::range(16, 16384));
  s->add_flag("--previews", synth.previews, "Also write tone-mapped PNGs into DIR/preview/");
  s->add_option("-o,--output", synth.out, "Dataset folder (created)")->required();
  cli::add_threads(*s, synth.threads);
  cli::add_progress(*s, synth.progress);
  return s;
}

CLI::App* add_lumitexels(CLI::App& app, LumitexelArgs& ltx) {
  namespace cli = fest::cli;
  auto* l = app.add_subcommand("lumitexels", "Resample the rig's HDR images onto the mesh: .ltx lumitexels");
  l->add_option("--mesh", ltx.mesh, "The mesh the rig is registered to")->required();
  l->add_option("--rig", ltx.rig, "Rig JSON (frame mesh or turntable)")->required();
  l->add_option("--root", ltx.root, "Folder the rig's image paths are relative to (default: the rig's session folder)");
  l->add_option("-o,--output", ltx.out, "Lumitexel file, - = standard output");
  l->add_option("--min-samples", ltx.o.min_samples, "Drop lumitexels with fewer samples")->check(fest::cli::range(1, 65535));
  l->add_option("--min-cos", ltx.o.min_cos, "Smallest cosine of light and view to the normal")->check(fest::cli::range(0.0, 1.0));
  l->add_option("--depth-eps", ltx.depth_eps_rel, "Depth and shadow tolerance, fraction of the bbox diagonal")
      ->check(fest::cli::range(0.0, 1.0));
  l->add_option("--shadow-res", ltx.o.shadow_resolution, "Shadow map size (0: the largest image side, 512..8192)")
      ->check(fest::cli::range(0, 16384));
  l->add_option("--atlas", ltx.atlas, "Also write the texture atlas of the home images' pixels (EXR; docs/brdffit.md §4)");
  l->add_option("--atlas-mesh", ltx.atlas_mesh, "The mesh with the atlas' texture coordinates (PLY; default: the "
                                                "--atlas path with .ply)");
  l->add_option("--report", ltx.report, "Counts and timings as JSON");
  cli::add_threads(*l, ltx.threads);
  cli::add_progress(*l, ltx.progress);
  return l;
}

CLI::App* add_register(CLI::App& app, RegisterArgs& reg) {
  namespace cli = fest::cli;
  auto* r = app.add_subcommand("register", "Silhouette registration of a photograph (or a turntable rig) to the mesh");
  r->add_option("--mesh", reg.mesh, "The mesh")->required();
  r->add_option("--mask", reg.mask, "Silhouette of the photograph (nonzero = object)");
  r->add_option("--camera", reg.camera, "cam.json: intrinsics and the initial pose");
  r->add_option("--rig", reg.rig, "Turntable mode: fit one camera and the table axis to all masks of the rig");
  r->add_option("--root", reg.root, "Folder the rig's paths are relative to (default: the rig's session folder)");
  r->add_flag("--auto", reg.o.automatic, "Ignore the initial pose: search orientations on SO(3)");
  r->add_flag("--fix-focal", reg.o.fix_focal, "Keep the camera's focal length (calibrated): fit the pose only");
  r->add_option("--orient-samples", reg.o.orient_samples, "Orientations tried by --auto")->check(fest::cli::range(1, 100000));
  r->add_option("--coarse-iters", reg.o.coarse_iters, "Simplex steps per orientation at 1/8 resolution")
      ->check(fest::cli::range(1, 10000));
  r->add_option("--keep", reg.o.keep, "Best orientations of --auto refined at every level")->check(fest::cli::range(1, 1000));
  r->add_option("--iters", reg.o.iters_per_level, "Simplex steps per pyramid level")->check(fest::cli::range(1, 100000));
  r->add_option("--max-xor", reg.max_xor, "Fail (exit 1) above this XOR fraction")->check(fest::cli::range(0.0, 10.0));
  r->add_option("--seed", reg.o.seed, "Seed of the orientation samples");
  r->add_option("-o,--output", reg.out, "Fitted cam.json (or rig), - = standard output");
  r->add_option("--report", reg.report, "XOR, evaluations, time as JSON");
  cli::add_threads(*r, reg.threads);
  cli::add_progress(*r, reg.progress);
  return r;
}

CLI::App* add_render(CLI::App& app, RenderArgs& ren) {
  namespace cli = fest::cli;
  auto* d = app.add_subcommand("render", "Render the mesh with Lafortune materials under a point light (linear EXR)");
  d->add_option("--mesh", ren.mesh, "The mesh")->required();
  d->add_option("--materials", ren.materials, "Materials JSON (truth.json of synth, or brdffit(1) MATERIALS)");
  d->add_option("--svbrdf", ren.svbrdf, "Fitted materials instead: .ltw of brdffit project (with --ltx); every "
                                         "triangle takes its lumitexels' majority cluster BRDF");
  d->add_option("--ltx", ren.ltx, "The lumitexel file the --svbrdf weights were made from");
  d->add_option("--camera", ren.camera, "cam.json");
  d->add_option("--light", ren.light, "light.json");
  d->add_option("--rig", ren.rig, "Take camera and light from a rig image (with --image)");
  d->add_option("--root", ren.root, "Folder the rig's paths are relative to");
  d->add_option("--image", ren.rig_image, "Index of the rig image")->check(fest::cli::non_negative);
  d->add_option("-o,--output", ren.out, "Radiance EXR, - = standard output")->required();
  d->add_option("--png", ren.png, "Also write a tone-mapped PNG");
  d->add_option("--exposure", ren.exposure, "Scale before tone mapping for --png")->check(fest::cli::positive);
  d->add_option("--mask-out", ren.mask_out, "Also write the object mask (PNG)");
  d->add_option("--env", ren.env, "Lat-long HDR environment map as background");
  d->add_option("--env-light", ren.env_light, "Diffuse environment light scale")->check(fest::cli::non_negative);
  d->add_option("--shadow-res", ren.shadow_res, "Shadow map size")->check(fest::cli::range(16, 16384));
  d->add_flag("--no-shadows", ren.no_shadows, "Skip the shadow test");
  cli::add_threads(*d, ren.threads);
  return d;
}

CLI::App* add_eval(CLI::App& app, EvalArgs& ev) {
  namespace cli = fest::cli;
  auto* e = app.add_subcommand("eval", "Compare a rendering with a photograph: RMSE, relative L2, PSNR as JSON");
  e->add_option("--photo", ev.photo, "Photograph (EXR/PFM radiance)")->required();
  e->add_option("--render", ev.render, "Rendering from the same camera and light")->required();
  e->add_option("--mask", ev.mask, "Compare inside this mask only");
  e->add_option("--error", ev.error, "Also write |photo - render| (EXR)");
  e->add_option("-o,--output", ev.out, "Metrics JSON, - = standard output");
  return e;
}

CLI::App* add_export(CLI::App& app, ExportArgs& ex) {
  namespace cli = fest::cli;
  auto* x = app.add_subcommand("export", "glTF 2.0 (or .glb) with the materials as metallic-roughness textures in a "
                                         "texture atlas (docs/brdffit.md §4, §6)");
  x->add_option("--mesh", ex.mesh, "The mesh")->required();
  x->add_option("--materials", ex.materials, "Materials JSON (truth.json of synth, or brdffit(1) MATERIALS)");
  x->add_option("--svbrdf", ex.svbrdf, "Fitted materials instead: .ltw of brdffit project (with --ltx); each texel "
                                       "takes the nearest lumitexel's blend of basis BRDFs");
  x->add_option("--ltx", ex.ltx, "The lumitexel file the --svbrdf weights were made from");
  x->add_option("--normals", ex.normals, "Refined normals (normals.ply of brdffit normals): also a normal map");
  x->add_option("--gltf", ex.out, "Output .gltf (PNG textures beside it), .glb (all in one), - = standard output "
                                  "(textures as data URIs)")->required();
  x->add_option("--texture-size", ex.texture_size, "About the atlas' longer side in texels")->check(fest::cli::range(16, 16384));
  x->add_option("--texel", ex.texel, "World units per texel instead of --texture-size")->check(fest::cli::positive);
  x->add_option("--gutter", ex.gutter, "Texels around each atlas chart")->check(fest::cli::range(0, 64));
  x->add_flag("--flat", ex.flat, "No textures: one constant material per BRDF, triangles by majority material");
  cli::add_threads(*x, ex.threads);
  return x;
}

CLI::App* add_info(CLI::App& app, InfoArgs& info) {
  namespace cli = fest::cli;
  auto* i = app.add_subcommand("info", "Describe a .ltx file as JSON; with --mesh, check that it belongs to that mesh");
  i->add_option("input", info.in, "Lumitexel file, - = standard input");
  i->add_option("--mesh", info.mesh, "Fail (exit 3) unless the file's mesh SHA-256 is this mesh's");
  return i;
}

CLI::App* add_fit(CLI::App& app, FitArgs& fit) {
  namespace cli = fest::cli;
  auto* f = app.add_subcommand("fit", "Fit one Lafortune BRDF to samples (CSV) or a MERL .binary; brdf.json to stdout");
  f->add_option("input", fit.input, "samples.csv: ux,uy,uz,vx,vy,vz,r,g,b (local frame; r = f u_z), - = stdin")->default_val("-");
  f->add_option("--merl", fit.merl, "Fit a MERL .binary BRDF table instead");
  f->add_flag("--angles", fit.angles, "Columns theta_i,phi_i,theta_o,phi_o,r,g,b (radians)");
  f->add_option("-o,--output", fit.output, "brdf.json (- = stdout)")->default_val("-");
  add_fit_flags(f, fit.fit);
  cli::add_progress(*f, fit.progress);
  return f;
}

CLI::App* add_cluster(CLI::App& app, ClusterArgs& cluster) {
  namespace cli = fest::cli;
  auto* c = app.add_subcommand("cluster", "Cluster lumitexels into materials by split and refit; clusters.json to stdout");
  c->add_option("input", cluster.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  c->add_option("-o,--output", cluster.output, "clusters.json (- = stdout)")->default_val("-");
  c->add_option_function<std::string>(
       "--clusters", [&cluster](const std::string& text) { cluster.clusters = cluster_count(text); },
       "Number of materials, or auto (split until --min-gain)")
      ->default_str("5");
  c->add_option("--split-scale", cluster.c.split_scale, "kappa: split step in standard deviations")->default_val(1.0);
  c->add_option("--split-iters", cluster.c.split_iters, "Refits per split at most")->default_val(10)->check(fest::cli::range(1, 10000));
  c->add_option("--stable", cluster.c.stable, "A split ends when fewer members change side")->default_val(0.005);
  c->add_option("--global-iters", cluster.c.global_iters, "Global reassignment rounds per split")->default_val(3)->check(fest::cli::range(0, 10000));
  c->add_option("--min-cluster", cluster.c.min_cluster, "Dissolve clusters below this fraction of lumitexels")->default_val(0.001);
  c->add_option("--min-gain", cluster.c.min_gain, "auto: stop when a split gains less (fraction of the 1-cluster error)")->default_val(0.02);
  c->add_option("--min-samples", cluster.min_samples, "Ignore lumitexels with fewer samples")->default_val(2)->check(fest::cli::range(1, 65535));
  add_fit_flags(c, cluster.fit);
  cli::add_progress(*c, cluster.progress);
  return c;
}

CLI::App* add_project(CLI::App& app, ProjectArgs& project) {
  namespace cli = fest::cli;
  auto* p = app.add_subcommand("project", "Per-lumitexel weights over per-cluster basis BRDFs; .ltw to stdout");
  p->add_option("input", project.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  p->add_option("--clusters", project.clusters_file, "clusters.json from brdffit cluster")->required();
  p->add_option("-o,--output", project.output, ".ltw output (- = stdout)")->default_val("-");
  p->add_option("--basis", project.basis, "Basis BRDFs per cluster")->default_val(4)->check(fest::cli::range(1, 64));
  cli::enum_words<fest::brdffit::WeightMode>(p->add_option("--weights", project.weights, "scalar (one per basis BRDF) or rgb (per channel)"),
                  {{"scalar", fest::brdffit::WeightMode::scalar}, {"rgb", fest::brdffit::WeightMode::rgb}})
      ->default_str("scalar");
  p->add_flag("--nonneg", project.nonneg, "Non-negative weights (NNLS) instead of the SVD solution");
  p->add_option("--split-scale", project.split_scale, "kappa of the trial split")->default_val(1.0);
  p->add_option("--split-iters", project.split_iters, "Refits of the trial split at most")->default_val(10)->check(fest::cli::range(1, 10000));
  p->add_option("--min-samples", project.min_samples, "Lumitexels with fewer samples get the pure cluster BRDF")->default_val(2)->check(fest::cli::range(1, 65535));
  p->add_option("--report", project.report, "Write timings and errors as JSON");
  cli::add_threads(*p, project.threads);
  cli::add_progress(*p, project.progress);
  return p;
}

CLI::App* add_normals(CLI::App& app, NormalsArgs& normals) {
  namespace cli = fest::cli;
  auto* n = app.add_subcommand("normals", "Refine normals against the projected BRDFs; normals.ply to stdout");
  n->add_option("input", normals.input, "Lumitexel file (.ltx), - = stdin")->default_val("-");
  n->add_option("--svbrdf", normals.svbrdf, ".ltw from brdffit project")->required();
  n->add_option("-o,--output", normals.output, "normals.ply (- = stdout)")->default_val("-");
  n->add_option("--normal-min-samples", normals.n.min_samples, "Refine lumitexels with at least this many samples")->default_val(5)->check(fest::cli::range(3, 65535));
  n->add_option("--max-tilt", normals.n.max_tilt_deg, "Largest tilt from the mesh normal (degrees)")->default_val(30);
  n->add_option("--alternate", normals.n.alternate, "Rounds of (re-projection, normals)")->default_val(1)->check(fest::cli::range(1, 1000));
  n->add_flag("--ascii", normals.ascii, "ASCII PLY instead of binary");
  n->add_option("--report", normals.report, "Write timings and residuals as JSON");
  cli::add_threads(*n, normals.threads);
  cli::add_progress(*n, normals.progress);
  return n;
}

CLI::App* add_factor(CLI::App& app, FactorArgs& factor) {
  namespace cli = fest::cli;
  auto* fa = app.add_subcommand("factor", "Separable approximation of one BRDF for display (Kautz & McCool): rank-1 "
                                          "factors g(half) h(difference) as EXR, errors as JSON");
  fa->add_option("--brdf", factor.brdf, "brdf.json (brdffit fit)")->required();
  fa->add_option("-o,--output", factor.prefix, "Prefix of PREFIXg.exr and PREFIXh.exr")->required();
  fa->add_option("--theta-bins", factor.theta_bins, "Cells in theta over [0, 90) degrees")->check(fest::cli::range(1, 1024));
  fa->add_option("--phi-bins", factor.phi_bins, "Cells in phi over [0, 360) degrees")->check(fest::cli::range(1, 1024));
  fa->add_flag("--no-compare", factor.no_compare, "Skip the (omega_o, omega_i) factorisation the report compares with");
  cli::add_threads(*fa, factor.threads);
  return fa;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = fest::cli;
  CLI::App app{"Spatially varying BRDFs from registered HDR photographs of a scanned object\n"
               "(Lensch et al.: lumitexels, Lafortune fits, material clustering, projection).",
               "brdffit"};
  cli::Common common;
  cli::add_common(app, common);
  app.require_subcommand(1);

  // ---- geometry stages
  SynthArgs synth;
  auto* s = add_synth(app, synth);
  LumitexelArgs ltx;
  auto* l = add_lumitexels(app, ltx);
  RegisterArgs reg;
  auto* r = add_register(app, reg);
  RenderArgs ren;
  auto* d = add_render(app, ren);
  EvalArgs ev;
  auto* e = add_eval(app, ev);
  ExportArgs ex;
  auto* x = add_export(app, ex);
  InfoArgs info;
  auto* i = add_info(app, info);
  // ---- materials stages
  FitArgs fit;
  auto* f = add_fit(app, fit);
  ClusterArgs cluster;
  auto* c = add_cluster(app, cluster);
  ProjectArgs project;
  auto* p = add_project(app, project);
  NormalsArgs normals;
  auto* n = add_normals(app, normals);
  // ---- factor
  FactorArgs factor;
  add_factor(app, factor);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See brdffit(1), ltx(5), ltw(5).");
  // The outer frame reports errors thrown while flags are parsed (--robust, --clusters).
  return fest::run_tool("brdffit", [&] {
    return cli::run(app, argc, argv, [&] {
      if (s->parsed()) return run_synth(synth);
      if (l->parsed()) return run_lumitexels(ltx);
      if (r->parsed()) return run_register(reg);
      if (d->parsed()) return run_render(ren);
      if (e->parsed()) return run_eval(ev);
      if (x->parsed()) return run_export(ex);
      if (i->parsed()) return run_info(info);
      if (f->parsed()) return run_fit(fit);
      if (c->parsed()) return run_cluster(cluster);
      if (p->parsed()) return run_project(project);
      if (n->parsed()) return run_normals(normals);
      return run_factor(factor);
    });
  });
}
