#pragma once
// facefit's subcommands (docs/facefit.md), each taking its typed options. main.cpp fills
// these from flags; everything else in this folder is the fest_facefit_app library.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "facefit/fit.hpp"
#include "formats/detect.hpp"

namespace fest::facefit_tool {

// Units of a numeric η: model units squared (scaled by the camera's s²) or pixels squared.
enum class EtaUnits { mm2, px2 };
// Where fitted vertices are written: model space (mm) or image space (u, v px, depth).
enum class Space { model, image };
// What `convert` imports.
enum class ModelSource { eos, npz, ply_set, mmb };

// --eta: a number >= 0, or chosen automatically (generalised cross-validation, evidence).
struct Eta {
  enum class Rule { number, gcv, evidence } rule = Rule::number;
  double value = 2;
};
// "2", "auto=gcv", "auto=evidence" -> Eta; a usage error otherwise.
Eta parse_eta(const std::string& text);

// --to of fit and sample: a mesh format; plya is ASCII PLY. Unset: from -o (binary PLY on
// standard output).
struct MeshOutput {
  formats::OutputFormat format;
  bool ascii = false;       // plya
  bool direct_ply = false;  // ply: binary PLY written straight from the float32 arrays
};
// The word of --to -> MeshOutput; a usage error for a word that is not a mesh format.
MeshOutput parse_mesh_output(const std::string& word);

struct FitArgs {
  std::string model, landmarks = "-", map;
  facefit::CameraKind camera = facefit::CameraKind::similarity;
  std::array<double, 2> center{150, 150};
  Eta eta;
  EtaUnits eta_units = EtaUnits::mm2;
  Space space = Space::model;
  std::string texture;
  facefit::NuisanceKind nuisance = facefit::NuisanceKind::free;
  std::string full_shape, coeffs, report, batch, output = "-", uncertainty;
  std::optional<MeshOutput> to;
  double scale = 1, yaw = 0, noise_sigma = 0, nuisance_sigma = 100, pts_origin = 1;
  bool noise_sigma_given = false, eta_given = false, skip_unmapped = false, fix_basis = false;
  int components = 0, iterations = 5, threads = 0;
  bool progress = false;  // --progress (--batch): fits done
};
int run_fit(const FitArgs& a);

struct BuildArgs {
  std::string output, list, landmarks, units = "mm", mask;
  std::vector<std::string> examples;
  int components = 0;
  double variance = 0;
  bool f64 = false;
  bool progress = false;  // --progress: meshes read, then the PCA
};
int run_build(const BuildArgs& a);

struct ConvertArgs {
  ModelSource from = ModelSource::eos;
  std::string input, output, landmarks, mask;
  double scale = 1;
  bool fix_basis = false;
};
int run_convert(const ConvertArgs& a);

struct InfoArgs {
  std::string model;
  bool fix_basis = false;
};
int run_info(const InfoArgs& a);

struct SampleArgs {
  std::string model, coeffs, output = "-";
  std::optional<MeshOutput> to;
  int random = 0;
  double sigma_scale = 1;
  unsigned long long seed = 1;
};
int run_sample(const SampleArgs& a);

struct ProjectArgs {
  std::string model, mesh, vertices;
  std::array<double, 2> center{150, 150};
  double scale = 1, yaw = 0, pitch = 0, noise_sigma = 0;
  unsigned long long seed = 1;
  bool by_vertex = false;
};
int run_project(const ProjectArgs& a);

struct EvalArgs {
  std::string truth, estimate, mask, output = "-", png;
  bool per_vertex = false;
};
int run_eval(const EvalArgs& a);

struct SweepArgs {
  std::string model, faces, vertices, mask;
  std::vector<double> etas{0, 1e-4, 1e-3, 1e-2, 0.1, 0.3, 1, 2, 3, 10, 100, 1000};
  std::vector<double> components;  // empty: all
  std::vector<double> noise{0};
  std::vector<double> yaw{0};
  bool summary = false;
  unsigned long long seed = 1;
};
int run_sweep(const SweepArgs& a);

struct SynthArgs {
  std::string output;
  int faces = 200, train = 100, resolution = 128;
  double detail = 1;
  unsigned long long seed = 1;
};
int run_synth(const SynthArgs& a);

}  // namespace fest::facefit_tool
