// facefit build / convert / info / sample: making, importing and inspecting models.

#include <sys/stat.h>

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "facefit/pca_build.hpp"
#include "facefit/rng.hpp"
#include "formats/facemodel/import.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/table/table_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

namespace {

facefit::Model build_from_meshes(const std::vector<std::string>& paths, const BuildArgs& a) {
  if (paths.size() < 2) throw usage_error("build needs at least 2 example meshes");
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Eigen::VectorXd first = read_shape(paths[0], &triangles);
  Eigen::MatrixXd X(first.size(), static_cast<Eigen::Index>(paths.size()));
  X.col(0) = first;
  for (std::size_t i = 1; i < paths.size(); ++i) {
    const Eigen::VectorXd v = read_shape(paths[i]);
    if (v.size() != first.size())
      throw bad_input("'{}' has {} vertices, '{}' has {}: meshes must be in correspondence", paths[i], v.size() / 3, paths[0],
                      first.size() / 3);
    X.col(static_cast<Eigen::Index>(i)) = v;
  }
  facefit::BuildOptions o;
  if (a.components < 0) throw usage_error("--components must be positive");
  o.components = static_cast<std::size_t>(a.components);
  if (a.variance < 0 || a.variance > 1) throw usage_error("--variance must be in (0, 1]");
  o.variance = a.variance;
  o.float_basis = !a.f64;
  facefit::Model m = facefit::build_model(X, 3, o);
  m.triangles = triangles;
  m.units = a.units;
  m.source = fmt::format("facefit build from {} meshes", paths.size());
  return m;
}

void attach_landmarks(facefit::Model& m, const std::string& landmarks, const std::string& mask) {
  if (!landmarks.empty()) m.landmarks = read_map(landmarks);
  if (!mask.empty()) m.eval_mask = read_vertex_indices(mask);
  facefit::check_model(m, false);
}

}  // namespace

int run_build(const BuildArgs& a) {
  std::vector<std::string> paths = a.examples;
  if (!a.list.empty())
    for (auto& p : read_list(a.list)) paths.push_back(p);
  facefit::Model m = build_from_meshes(paths, a);
  attach_landmarks(m, a.landmarks, a.mask);
  write_output(a.output, formats::write_mmb(m));
  return 0;
}

int run_convert(const ConvertArgs& a) {
  if (!(a.scale > 0) || !std::isfinite(a.scale)) throw usage_error("--scale must be positive");
  facefit::Model m;
  std::string warnings;
  if (a.from == ModelSource::eos) {
    m = formats::read_eos_model(read_input(a.input), a.input);
  } else if (a.from == ModelSource::npz) {
    m = formats::read_npz_model(a.input, &warnings);
  } else if (a.from == ModelSource::mmb) {
    formats::MmbReadOptions o;
    o.fix_basis = a.fix_basis;
    m = formats::read_mmb(a.input, o, &warnings);
  } else {
    BuildArgs b;
    m = build_from_meshes(read_list(a.input), b);
  }
  if (!warnings.empty()) warn(warnings);
  if (a.scale != 1) {
    for (auto& v : m.mean) v *= a.scale;
    for (auto& s : m.sigma) s *= a.scale;
  }
  const auto fixed = facefit::check_model(m, a.fix_basis);
  if (fixed.reordered) warn("sigma was not descending: components reordered");
  if (fixed.renormalised) warn("basis columns renormalised (--fix-basis)");
  attach_landmarks(m, a.landmarks, a.mask);
  // µm-sized models (BFM 2009) show as a bounding box over 1000 units.
  double lo = 1e300, hi = -1e300;
  for (double v : m.mean) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (hi - lo > 1000) warn(fmt::format("model extent is {:.4g} units: if it is in µm use --scale 0.001 for mm", hi - lo));
  write_output(a.output, formats::write_mmb(m));
  return 0;
}

int run_info(const InfoArgs& a) {
  const std::string path = model_path(a.model);
  const facefit::Model m = load_model(a.model, a.fix_basis);
  nlohmann::json j = {{"file", path},
                      {"format", "mmb"},
                      {"dims", m.dims},
                      {"points", m.points},
                      {"components", m.components},
                      {"units", m.units},
                      {"source", m.source},
                      {"license", m.license},
                      {"training_examples", m.training_examples},
                      {"basis_dtype", m.basis_type == facefit::Dtype::f32 ? "f32" : "f64"},
                      {"triangles", m.triangles.size()},
                      {"landmarks", m.landmarks.size()},
                      {"eval_mask", m.eval_mask.size()},
                      {"sigma_first", m.sigma.front()},
                      {"sigma_last", m.sigma.back()},
                      {"total_stddev", 0.0}};
  double var = 0;
  for (double s : m.sigma) var += s * s;
  j["total_stddev"] = std::sqrt(var);
  j["rms_per_vertex"] = std::sqrt(var / static_cast<double>(m.points));
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t p = 0; p < m.points; ++p)
    for (int e = 0; e < m.dims; ++e) {
      lo[e] = std::min(lo[e], m.mean[p * static_cast<std::size_t>(m.dims) + static_cast<std::size_t>(e)]);
      hi[e] = std::max(hi[e], m.mean[p * static_cast<std::size_t>(m.dims) + static_cast<std::size_t>(e)]);
    }
  j["mean_bbox"] = {{"min", std::vector<double>(lo, lo + m.dims)}, {"max", std::vector<double>(hi, hi + m.dims)}};
  write_output("-", formats::write_json(j));
  return 0;
}

int run_sample(const SampleArgs& a) {
  const facefit::Model m = load_model(a.model);
  const auto k = static_cast<Eigen::Index>(m.components);
  std::vector<Eigen::VectorXd> coeffs;
  if (!a.coeffs.empty()) {
    const Table t = formats::read_table(read_input(a.coeffs), formats::Format::tsv);
    const std::size_t ci = t.find("c"), ii = t.find("index");
    if (ci == Table::npos) throw bad_input("coefficient table needs a column 'c' ({})", a.coeffs);
    Eigen::VectorXd c = Eigen::VectorXd::Zero(k);
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const double idx = ii == Table::npos ? static_cast<double>(r) : t.columns[ii][r];
      if (!(idx >= 0 && idx < static_cast<double>(k)) || idx != std::floor(idx))
        throw bad_input("coefficient index {} outside 0..{} ({})", idx, k - 1, a.coeffs);
      if (!std::isfinite(t.columns[ci][r])) throw bad_input("coefficient {} is not finite ({})", idx, a.coeffs);
      c(static_cast<Eigen::Index>(idx)) = t.columns[ci][r];
    }
    coeffs.push_back(c);
  } else if (a.random > 0) {
    facefit::Rng rng(a.seed);
    for (int i = 0; i < a.random; ++i) {
      Eigen::VectorXd c(k);
      for (Eigen::Index j = 0; j < k; ++j) c(j) = a.sigma_scale * rng.normal();
      coeffs.push_back(c);
    }
  } else {
    coeffs.push_back(Eigen::VectorXd::Zero(k));  // the mean face
  }
  if (coeffs.size() == 1) {
    write_shape(facefit::reconstruct(m, coeffs[0]), m.dims, m.triangles, a.output, a.to);
    return 0;
  }
  if (is_stdio(a.output)) throw usage_error("--random {} writes several meshes: -o must name a folder", a.random);
  ::mkdir(a.output.c_str(), 0777);
  for (std::size_t i = 0; i < coeffs.size(); ++i)
    write_mesh_to(shape_to_mesh(facefit::reconstruct(m, coeffs[i]), m.dims, m.triangles),
                  fmt::format("{}/sample{:03d}.ply", a.output, i + 1), a.to);
  return 0;
}

}  // namespace fest::facefit_tool
