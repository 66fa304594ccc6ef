#pragma once
// brdffit's subcommands (docs/brdffit.md), each taking its typed options. main.cpp fills
// these from flags and calls one function per subcommand; everything else in this folder
// is the fest_brdffit_app library. Every function returns the exit status (0) or throws
// fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>

#include "brdffit/cluster.hpp"
#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/normals.hpp"
#include "brdffit/project.hpp"
#include "brdffit/registration.hpp"
#include "brdffit/synthetic_scene.hpp"

namespace fest::brdffit_tool {

// ---- geometry stages (docs/brdffit.md §4, §6) --------------------------------------

struct SynthArgs {
  std::string mesh;  // empty: an icosphere
  int sphere_level = 4;
  double sphere_radius = 50;
  int material_count = 3;      // built-in materials on surface patches (without materials_file)
  std::string materials_file;  // a materials JSON instead of material_count
  brdffit::TurntableSetup setup;
  double noise = 0;
  std::uint64_t seed = 1;
  std::string env;
  double env_light = 0;
  double perturb_deg = 0;
  int shadow_res = 2048;
  bool previews = false;
  std::string out;
  int threads = 0;
  bool progress = false;  // --progress: images rendered
};
int run_synth(const SynthArgs& a);

struct LumitexelArgs {
  std::string mesh, rig, root, out = "-", report, atlas, atlas_mesh;
  brdffit::LumitexelOptions o;
  double depth_eps_rel = 0.002;
  int threads = 0;
  bool progress = false;  // --progress: images resampled
};
int run_lumitexels(const LumitexelArgs& a);

struct RegisterArgs {
  std::string mesh, mask, camera, rig, root, out = "-", report;
  brdffit::RegistrationOptions o;
  double max_xor = 0.05;
  int threads = 0;
  bool progress = false;  // --progress: simplex runs
};
int run_register(const RegisterArgs& a);

struct RenderArgs {
  std::string mesh, materials, svbrdf, ltx, camera, light, rig, root, out, png, mask_out, env;
  int rig_image = -1;
  double exposure = 1, env_light = 0;
  int shadow_res = 2048;
  bool no_shadows = false;
  int threads = 0;
};
int run_render(const RenderArgs& a);

struct EvalArgs {
  std::string photo, render, mask, error, out = "-";
};
int run_eval(const EvalArgs& a);

struct ExportArgs {
  std::string mesh, materials, svbrdf, ltx, normals, out;
  bool flat = false;
  int texture_size = 1024, gutter = 2, threads = 0;
  double texel = 0;
};
int run_export(const ExportArgs& a);

struct InfoArgs {
  std::string in = "-", mesh;
};
int run_info(const InfoArgs& a);

// ---- materials stages (docs/brdffit.md §3, §5, §6) ------------------------------------

// What every fit-based subcommand shares.
struct FitFlags {
  int lobes = 1;
  bool shared = false;
  double max_lobe_albedo = 1.0;
  int starts = 4;
  double huber_delta = 0;  // > 0: Huber loss with this threshold; 0: squared error
  std::size_t subsample = 200000;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string report;
};

struct FitArgs {
  FitFlags fit;
  std::string input = "-", merl, output = "-";
  bool angles = false;
  bool progress = false;  // --progress: LM iterations of the starts
};
int run_fit(const FitArgs& a);

struct ClusterArgs {
  FitFlags fit;
  std::string input = "-", output = "-";
  int clusters = 5;  // 0: auto (split until the gain falls below c.min_gain)
  brdffit::ClusterOptions c;
  int min_samples = 2;
  bool progress = false;  // --progress: clusters made
};
int run_cluster(const ClusterArgs& a);

struct ProjectArgs {
  std::string input = "-", output = "-", clusters_file;
  brdffit::WeightMode weights = brdffit::WeightMode::scalar;
  int basis = 4;
  bool nonneg = false;
  double split_scale = 1.0;
  int split_iters = 10, threads = 0, min_samples = 2;
  std::string report;
  bool progress = false;  // --progress: nearest clusters, bases, weights, error
};
int run_project(const ProjectArgs& a);

struct NormalsArgs {
  std::string input = "-", output = "-", svbrdf;
  brdffit::NormalOptions n;
  int threads = 0;
  bool ascii = false;
  std::string report;
  bool progress = false;  // --progress: lumitexels refined
};
int run_normals(const NormalsArgs& a);

// ---- factor (docs/brdffit.md §6) ---------------------------------------------------

struct FactorArgs {
  std::string brdf, prefix;
  int theta_bins = 32, phi_bins = 64, threads = 0;
  bool no_compare = false;
};
int run_factor(const FactorArgs& a);

}  // namespace fest::brdffit_tool
