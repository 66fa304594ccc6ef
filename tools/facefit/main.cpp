// facefit: complete 3-D face shape from a few 2-D feature points (Blanz & Vetter,
// chapter 1; docs/facefit.md). Subcommands in the manner of git; this file only maps
// flags onto the typed options of commands.hpp, one call per subcommand.

#include <utility>
#include <vector>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

using namespace fest::facefit_tool;
namespace ff = fest::facefit;

const std::vector<std::pair<std::string, ff::CameraKind>> kCameras{
    {"fixed", ff::CameraKind::fixed}, {"similarity", ff::CameraKind::similarity}, {"affine", ff::CameraKind::affine}};
const std::vector<std::pair<std::string, ff::NuisanceKind>> kNuisances{
    {"free", ff::NuisanceKind::free}, {"penalized", ff::NuisanceKind::penalized}, {"none", ff::NuisanceKind::none}};
const std::vector<std::pair<std::string, EtaUnits>> kEtaUnits{{"mm2", EtaUnits::mm2}, {"px2", EtaUnits::px2}};
const std::vector<std::pair<std::string, Space>> kSpaces{{"model", Space::model}, {"image", Space::image}};
const std::vector<std::pair<std::string, ModelSource>> kSources{
    {"eos", ModelSource::eos}, {"npz", ModelSource::npz}, {"mmb", ModelSource::mmb}, {"ply-set", ModelSource::ply_set}};

// Landmark noise in pixels: beyond a million pixels no photograph is meant, and η = S²
// (px²) stays far from overflowing.
constexpr double kMaxNoisePx = 1e6;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Complete 3-D face shape from a few 2-D feature points with a morphable model\n"
               "(regularised closed-form Bayesian fit; Blanz & Vetter).",
               "facefit"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 numerical failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See facefit(1) and mmb(5).");

  FitArgs fit;
  auto* f = app.add_subcommand("fit", "Fit the model to landmarks; the complete mesh to standard output or -o");
  f->add_option("-m,--model", fit.model, "Model file (.mmb); default $FACEFIT_MODEL");
  f->add_option("--landmarks", fit.landmarks, "Landmark TSV (id|vertex u v [sigma]) or iBUG .pts; - = stdin")->default_val("-");
  f->add_option("--map", fit.map, "Landmark-to-vertex map (TSV or eos TOML); default: the model's");
  fest::cli::enum_words(f->add_option("--camera", fit.camera, "fixed | similarity | affine"), kCameras)->default_str("similarity");
  f->add_option("--scale", fit.scale, "Fixed camera: px per model unit")->default_val(1);
  f->add_option("--center", fit.center, "Fixed camera: image position U,V of the model origin")->delimiter(',')->default_str("150,150");
  f->add_option("--yaw", fit.yaw, "Fixed camera: rotation about the vertical axis (degrees)")->default_val(0);
  std::string eta_text = "2";
  auto* eta = f->add_option("--eta", eta_text, "η (>= 0), auto=gcv or auto=evidence")->default_val("2");
  fest::cli::enum_words(f->add_option("--eta-units", fit.eta_units, "Units of a numeric --eta: mm2 (scaled by s²) or px2"), kEtaUnits)->default_str("mm2");
  auto* noise = f->add_option("--noise-sigma", fit.noise_sigma, "Landmark noise (px): η = S² px² unless --eta is given")
      ->check(fest::cli::range(0.0, kMaxNoisePx));
  f->add_option("--components", fit.components, "Use the first K components (0 = all)")->default_val(0)
      ->check(fest::cli::non_negative);
  fest::cli::enum_words(f->add_option("--nuisance", fit.nuisance, "Similarity camera: free | penalized | none"), kNuisances)->default_str("free");
  f->add_option("--nuisance-sigma", fit.nuisance_sigma, "Prior std of penalized nuisance columns")->default_val(100);
  f->add_option("--iterations", fit.iterations, "Affine camera: camera/shape alternations")->default_val(5)->check(fest::cli::range(1, 1000));
  f->add_option("--full-shape", fit.full_shape, "Project a complete mesh into the model (L = id) instead of landmarks");
  f->add_option("--uncertainty", fit.uncertainty, "Write per-vertex posterior std (model units) as TSV");
  f->add_option("--coeffs", fit.coeffs, "Write the coefficients as TSV (index c sigma)");
  f->add_option("--report", fit.report, "Write a JSON report (η, camera, errors, timings)");
  f->add_option("--texture", fit.texture, "Photo the landmarks come from: visible vertices get its colours (PLY red green blue)");
  fest::cli::enum_words(f->add_option("--space", fit.space, "Output vertices in model space (mm) or image space (u, v px, depth)"), kSpaces)->default_str("model");
  f->add_option("--batch", fit.batch, "File of 'landmarks output' lines; output .tsv = coefficients only");
  f->add_option("-o,--output", fit.output, "Mesh output (- = stdout, binary PLY)")->default_val("-");
  std::string fit_to, sample_to;
  f->add_option("--to", fit_to, "Mesh format: ply | plya | obj | off");
  f->add_flag("--skip-unmapped", fit.skip_unmapped, "Ignore landmark ids the map lacks (warn)");
  f->add_option("--pts-origin", fit.pts_origin, "Subtracted from .pts coordinates (iBUG: 1)")->default_val(1);
  f->add_flag("--fix-basis", fit.fix_basis, "Renormalise basis columns that are not unit length");
  fest::cli::add_threads(*f, fit.threads);
  fest::cli::add_progress(*f, fit.progress);

  BuildArgs build;
  auto* b = app.add_subcommand("build", "Build a PCA model from meshes in correspondence");
  b->add_option("-o,--output", build.output, "Model file to write (.mmb)")->required();
  b->add_option("--components", build.components, "Keep at most K components (0 = all, m-1)")->default_val(0)
      ->check(fest::cli::non_negative);
  b->add_option("--variance", build.variance, "Keep the fewest components explaining this fraction")->default_val(0)
      ->check(fest::cli::range(0.0, 1.0));
  b->add_option("--landmarks", build.landmarks, "Landmark-to-vertex map stored in the model");
  b->add_option("--mask", build.mask, "Evaluation mask (vertex set) stored in the model");
  b->add_option("--units", build.units, "Length unit of the meshes")->default_val("mm");
  b->add_option("--list", build.list, "File listing example meshes, one per line");
  b->add_flag("--f64", build.f64, "Store the basis in double precision (default float32)");
  b->add_option("examples", build.examples, "Example meshes")->allow_extra_args(false);
  fest::cli::add_progress(*b, build.progress);

  ConvertArgs conv;
  auto* c = app.add_subcommand("convert", "Import a model (eos .bin, NumPy .npz, mesh list, .mmb) to .mmb");
  fest::cli::enum_words(c->add_option("--from", conv.from, "eos | npz | ply-set | mmb")->required(), kSources);
  c->add_option("input", conv.input, "Input file (for ply-set: a list of meshes)")->required();
  c->add_option("-o,--output", conv.output, "Model file to write (.mmb)")->required();
  c->add_option("--scale", conv.scale, "Multiply mean and sigma (BFM 2009 µm -> mm: 0.001)")->default_val(1);
  c->add_option("--landmarks", conv.landmarks, "Landmark-to-vertex map (eos TOML or TSV) to store");
  c->add_option("--mask", conv.mask, "Evaluation mask (vertex set) to store");
  c->add_flag("--fix-basis", conv.fix_basis, "Renormalise basis columns that are not unit length");

  InfoArgs info;
  auto* i = app.add_subcommand("info", "Describe a model as JSON");
  i->add_option("-m,--model", info.model, "Model file; default $FACEFIT_MODEL");
  i->add_flag("--fix-basis", info.fix_basis, "Renormalise basis columns that are not unit length");

  SampleArgs sample;
  auto* s = app.add_subcommand("sample", "Faces from coefficients, at random, or the mean");
  s->add_option("-m,--model", sample.model, "Model file; default $FACEFIT_MODEL");
  s->add_option("--coeffs", sample.coeffs, "Coefficient TSV (index c)");
  s->add_option("--random", sample.random, "Draw N faces c ~ N(0, sigma-scale² I)")->default_val(0)
      ->check(fest::cli::non_negative);
  s->add_option("--sigma-scale", sample.sigma_scale, "Scale of random coefficients")->default_val(1);
  s->add_option("--seed", sample.seed, "Random seed")->default_val(1);
  s->add_option("-o,--output", sample.output, "Mesh (one face) or folder (several)")->default_val("-");
  s->add_option("--to", sample_to, "Mesh format: ply | plya | obj | off");

  ProjectArgs proj;
  auto* p = app.add_subcommand("project", "Landmarks of a face under a scaled orthographic camera");
  p->add_option("-m,--model", proj.model, "Model whose mean face is projected");
  p->add_option("--mesh", proj.mesh, "Face mesh to project instead of the model's mean");
  p->add_option("--vertices", proj.vertices, "Vertex set (name vertex)")->required();
  p->add_option("--scale", proj.scale, "px per model unit")->default_val(1);
  p->add_option("--center", proj.center, "Image position of the model origin U,V")->delimiter(',')->default_str("150,150");
  p->add_option("--yaw", proj.yaw, "Head rotation about the vertical axis (degrees)")->default_val(0);
  p->add_option("--pitch", proj.pitch, "Head rotation about the horizontal axis (degrees)")->default_val(0);
  p->add_option("--noise-sigma", proj.noise_sigma, "Gaussian noise per coordinate (px)")->default_val(0)
      ->check(fest::cli::range(0.0, kMaxNoisePx));
  p->add_option("--seed", proj.seed, "Random seed of the noise")->default_val(1);
  p->add_flag("--by-vertex", proj.by_vertex, "Write 'vertex u v' instead of 'id u v'");

  EvalArgs ev;
  auto* e = app.add_subcommand("eval", "Per-vertex 3-D error of an estimate against the truth");
  e->add_option("--truth", ev.truth, "True mesh")->required();
  e->add_option("--estimate", ev.estimate, "Estimated mesh (same vertex order)")->required();
  e->add_option("--mask", ev.mask, "Vertex set to evaluate (default all)");
  e->add_flag("--per-vertex", ev.per_vertex, "One row per vertex instead of the summary");
  e->add_option("--png", ev.png, "Render truth, estimate and error map side by side to a PNG");
  e->add_option("-o,--output", ev.output, "TSV output")->default_val("-");

  SweepArgs sw;
  auto* w = app.add_subcommand("sweep", "The chapter's experiment: error against η over a set of faces");
  w->add_option("-m,--model", sw.model, "Model file; default $FACEFIT_MODEL");
  w->add_option("--faces", sw.faces, "List of true face meshes")->required();
  w->add_option("--vertices", sw.vertices, "Feature vertex set")->required();
  w->add_option("--etas", sw.etas, "Comma-separated η values (px²)")->delimiter(',')->allow_extra_args(false)->default_str("0,1e-4,1e-3,1e-2,0.1,0.3,1,2,3,10,100,1000");
  w->add_option("--components", sw.components, "Comma-separated component counts (default all)")->delimiter(',')->allow_extra_args(false);
  w->add_option("--noise-sigma", sw.noise, "Comma-separated landmark noise levels (px)")->delimiter(',')->allow_extra_args(false)->default_str("0")
      ->check(fest::cli::range(0.0, kMaxNoisePx));
  w->add_option("--yaw", sw.yaw, "Comma-separated rotations of the solver's L (degrees; fig. 1.6)")->delimiter(',')->allow_extra_args(false)->default_str("0");
  w->add_option("--mask", sw.mask, "Evaluation vertex set (default: the model's eval mask)");
  w->add_option("--seed", sw.seed, "Noise seed")->default_val(1);
  w->add_flag("--summary", sw.summary, "Means over faces per setting and η");

  SynthArgs sy;
  auto* y = app.add_subcommand("synth", "Write the synthetic face population, landmark sets and mask");
  y->add_option("-o,--out", sy.output, "Output folder")->required();
  y->add_option("--faces", sy.faces, "Number of faces")->default_val(200)->check(fest::cli::range(2, 100000));
  y->add_option("--train", sy.train, "How many of them are training faces")->default_val(100)->check(fest::cli::range(2, 100000));
  y->add_option("--resolution", sy.resolution, "Grid resolution R (R² vertices)")->default_val(128)->check(fest::cli::range(16, 2048));
  y->add_option("--detail-mm", sy.detail, "Amplitude of the individual detail (mm)")->default_val(1);
  y->add_option("--seed", sy.seed, "Random seed")->default_val(1);

  return fest::cli::run(app, argc, argv, [&]() -> int {
    if (*f) {
      fit.eta_given = eta->count() > 0;
      fit.noise_sigma_given = noise->count() > 0;
      fit.eta = parse_eta(eta_text);
      if (!fit_to.empty()) fit.to = parse_mesh_output(fit_to);
      return run_fit(fit);
    }
    if (*b) return run_build(build);
    if (*c) return run_convert(conv);
    if (*i) return run_info(info);
    if (*s) {
      if (!sample_to.empty()) sample.to = parse_mesh_output(sample_to);
      return run_sample(sample);
    }
    if (*p) return run_project(proj);
    if (*e) return run_eval(ev);
    if (*w) return run_sweep(sw);
    if (*y) return run_synth(sy);
    return 2;
  });
}
