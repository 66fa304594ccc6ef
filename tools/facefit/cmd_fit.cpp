// facefit fit: landmarks -> complete mesh (docs/facefit.md §2-§4).

#include <chrono>
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "face_files.hpp"
#include "core/error.hpp"
#include "core/field_lines.hpp"
#include "core/stopwatch.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "facefit/fit.hpp"
#include "facefit/render.hpp"
#include "formats/facemodel/landmarks_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/mesh/indexed_ply.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

namespace {

facefit::FitOptions fit_options(const FitArgs& a) {
  facefit::FitOptions o;
  o.camera = a.camera;
  o.fixed_camera = facefit::orthographic_camera(a.scale, {a.center[0], a.center[1]}, a.yaw);
  o.nuisance = a.nuisance;
  o.nuisance_sigma = a.nuisance_sigma;
  if (a.noise_sigma_given) {
    if (!(a.noise_sigma > 0)) throw usage_error("--noise-sigma must be positive");
    o.sigma_ref = a.noise_sigma;
  }
  if (a.eta.rule == Eta::Rule::gcv) {
    o.eta_mode = facefit::EtaMode::gcv;
  } else if (a.eta.rule == Eta::Rule::evidence) {
    o.eta_mode = facefit::EtaMode::evidence;
  } else if (a.noise_sigma_given && !a.eta_given) {
    // The chapter's finding: the best η is the landmark noise variance, in px².
    o.eta = a.noise_sigma * a.noise_sigma;
    o.eta_in_model_units = false;
  } else {
    o.eta = a.eta.value;
    o.eta_in_model_units = a.eta_units == EtaUnits::mm2;
  }
  if (a.iterations < 1) throw usage_error("--iterations must be at least 1");
  o.iterations = a.iterations;
  return o;
}

facefit::Landmarks load_landmarks(const FitArgs& a, const std::string& path, const facefit::Model& model) {
  const std::string source = input_name(path);
  const auto entries = formats::read_landmarks(read_text(path), source, a.pts_origin);
  facefit::LandmarkMap map = model.landmarks;
  if (!a.map.empty()) map = read_map(a.map);
  if (!a.skip_unmapped)  // the first unmapped id, named with the flag that would skip it
    for (const auto& e : entries)
      if (!e.by_vertex && map.find(e.id) == map.end())
        throw bad_input("landmark id '{}' is not in the landmark map ({}:{}; --skip-unmapped ignores it)", e.id, source, e.line);
  std::size_t skipped = 0;
  auto lm = facefit::resolve_landmarks(entries, map, a.skip_unmapped, &skipped, source);
  if (skipped > 0) warn(fmt::format("{} landmark(s) not in the map were skipped ({})", skipped, source));
  try {
    facefit::check_landmarks(model, lm);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), source));
  }
  return lm;
}

nlohmann::json report_of(const facefit::FitResult& r, const facefit::Landmarks& lm, const facefit::Model& model) {
  nlohmann::json j;
  j["eta"] = r.eta_px;
  j["eta_units"] = "px2";
  j["eta_source"] = r.eta_source;
  const auto pose = facefit::decompose_camera(r.camera);
  nlohmann::json P = nlohmann::json::array();
  for (int d = 0; d < 2; ++d) P.push_back({r.camera(d, 0), r.camera(d, 1), r.camera(d, 2), r.camera(d, 3)});
  j["camera"] = {{"P", P}, {"s", pose.scale}, {"t", {pose.translation.x(), pose.translation.y()}}, {"yaw_deg", pose.yaw_deg},
                 {"pitch_deg", pose.pitch_deg}};
  j["f"] = lm.size();
  j["l"] = 2 * lm.size();
  j["k"] = model.components;
  j["singular_values"] = std::vector<double>(r.singular_values.data(), r.singular_values.data() + r.singular_values.size());
  j["effective_dof"] = r.effective_dof;
  j["E_r"] = r.E_r;
  j["E_r_rms"] = r.E_r_rms;
  j["norm_c"] = r.norm_c;
  nlohmann::json per = nlohmann::json::array();
  for (std::size_t a = 0; a < lm.size(); ++a)
    per.push_back({{"id", lm.id[a]}, {"vertex", lm.vertex[a]}, {"du", r.residuals(0, static_cast<Eigen::Index>(a))},
                   {"dv", r.residuals(1, static_cast<Eigen::Index>(a))}});
  j["per_landmark"] = per;
  if (r.nuisance.size() == 3) j["nuisance"] = {{"tx", r.nuisance(0)}, {"ty", r.nuisance(1)}, {"s", r.nuisance(2)}};
  j["iterations"] = r.iterations;
  return j;
}

std::string coeffs_tsv(const facefit::FitResult& r, const facefit::Model& model) {
  std::string out = "index\tc\tsigma\n";
  for (Eigen::Index i = 0; i < r.c.size(); ++i)
    out += fmt::format("{}\t{:.9g}\t{:.9g}\n", i, r.c(i), model.sigma[static_cast<std::size_t>(i)]);
  return out;
}

// Texture transfer (docs/facefit.md §4, the chapter's figure 1.1): each vertex projected with the
// fitted camera, tested against a depth buffer at the photo's resolution, coloured by a
// bilinear sample of the photo; hidden vertices stay grey (128).
fest::Mesh textured_mesh(const std::string& path, const facefit::Model& model, const facefit::FitResult& r,
                         const Eigen::VectorXd& output_shape, std::size_t* visible_count) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::image) throw bad_input("--texture: '{}' is not an image", path);
  const Image img = formats::parse(in, formats::read_image);
  cv::Mat rgb;
  const cv::Mat& px = img.pixels;
  double scale = px.depth() == CV_8U ? 1.0 : px.depth() == CV_16U ? 1.0 / 257 : 255.0;
  px.convertTo(rgb, CV_MAKETYPE(CV_32F, px.channels()), scale);
  const Eigen::VectorXd image_shape = facefit::to_image_space(r.camera, r.shape);
  const auto visible = facefit::vertex_visibility(image_shape, model.triangles, rgb.cols, rgb.rows, 0.5);
  Mesh mesh = shape_to_mesh(output_shape, model.dims, model.triangles);
  mesh.request_vertex_colors();
  *visible_count = 0;
  for (auto vh : mesh.vertices()) {
    const auto j = static_cast<std::size_t>(vh.idx());
    Mesh::Color c(128, 128, 128);
    if (visible[j]) {
      ++*visible_count;
      const double u = std::clamp(image_shape(3 * vh.idx()), 0.0, rgb.cols - 1.0), v = std::clamp(image_shape(3 * vh.idx() + 1), 0.0, rgb.rows - 1.0);
      const int x0 = static_cast<int>(u), y0 = static_cast<int>(v);
      const int x1 = std::min(x0 + 1, rgb.cols - 1), y1 = std::min(y0 + 1, rgb.rows - 1);
      const double fx = u - x0, fy = v - y0;
      for (int ch = 0; ch < 3; ++ch) {
        const int k = std::min(ch, rgb.channels() - 1);
        auto at = [&](int y, int x) { return static_cast<double>(rgb.ptr<float>(y)[x * rgb.channels() + k]); };
        const double value = (1 - fy) * ((1 - fx) * at(y0, x0) + fx * at(y0, x1)) + fy * ((1 - fx) * at(y1, x0) + fx * at(y1, x1));
        c[ch] = static_cast<unsigned char>(std::clamp(std::lround(value), 0L, 255L));
      }
    }
    mesh.set_color(vh, c);
  }
  return mesh;
}

int run_full_shape(const FitArgs& a, const facefit::Model& model) {
  const Eigen::VectorXd shape = read_shape(a.full_shape);
  if (static_cast<std::size_t>(shape.size()) != 3 * model.points)
    throw bad_input("mesh has {} vertices, the model {} ({})", shape.size() / 3, model.points, a.full_shape);
  if (a.eta.rule != Eta::Rule::number || !(a.eta.value >= 0)) throw usage_error("--full-shape needs a numeric --eta >= 0 (mm²)");
  const double eta = a.eta.value;
  Eigen::VectorXd c;
  const Eigen::VectorXd out = facefit::fit_full_shape(model, shape, eta, &c);
  if (!a.coeffs.empty()) {
    facefit::FitResult r;
    r.c = c;
    write_output(a.coeffs, coeffs_tsv(r, model));
  }
  write_shape(out, model.dims, model.triangles, a.output, a.to);
  return 0;
}

int run_batch(const FitArgs& a, const facefit::Model& model, facefit::FitOptions opt) {
  // Lines "landmarks.tsv output" (output .tsv: coefficients only, no mesh).
  const std::string text = read_text(a.batch);
  std::string dir;
  if (const auto slash = a.batch.rfind('/'); slash != std::string::npos) dir = a.batch.substr(0, slash + 1);
  std::vector<std::pair<std::string, std::string>> jobs;
  for (const FieldLine& l : field_lines(text, true)) {
    const auto& f = l.fields;
    if (f.size() != 2) throw bad_input("batch list: expected 'landmarks output' ({}:{})", a.batch, l.number);
    auto rel = [&](const std::string& p) { return p[0] == '/' ? p : dir + p; };
    jobs.emplace_back(rel(f[0]), rel(f[1]));
  }
  // Shared across the batch: the similarity plan (one SVD for one landmark map), the
  // float32 vertex buffer and the PLY encoder with its face block (same triangles every fit).
  facefit::FitCache cache;
  std::vector<float> xyz;
  std::optional<formats::IndexedPlyEncoder> ply;
  Progress bar("facefit fit", jobs.size(), progress_wanted(a.progress));
  for (const auto& [in, out] : jobs) {
    const auto lm = load_landmarks(a, in, model);
    const bool coeffs_only = out.size() > 4 && out.compare(out.size() - 4, 4, ".tsv") == 0;
    const bool direct_ply = !coeffs_only && model.dims == 3 && writes_binary_ply(out, a.to);
    opt.reconstruct = !coeffs_only && !direct_ply;
    const auto r = facefit::fit_landmarks(model, lm, opt, &cache);
    if (coeffs_only) {
      write_output(out, coeffs_tsv(r, model));
    } else if (direct_ply) {
      if (!ply) ply.emplace(model.points, model.triangles);
      xyz.resize(model.n());
      facefit::reconstruct_f32(model, r.c, xyz.data());
      if (!Eigen::Map<const Eigen::VectorXf>(xyz.data(), static_cast<Eigen::Index>(xyz.size())).allFinite())
        throw runtime_failure("the fit produced non-finite coordinates ({})", in);
      write_output(out, ply->encode(xyz.data()));
    } else {
      write_shape(r.shape, model.dims, model.triangles, out, a.to);
    }
    bar.advance();
  }
  bar.finish();
  return 0;
}

}  // namespace

int run_fit(const FitArgs& a) {
  auto t0 = SteadyClock::now();
  facefit::FitOptions opt = fit_options(a);
  facefit::Model full = load_model(a.model, a.fix_basis);
  if (a.components > 0 && static_cast<std::size_t>(a.components) > full.components)
    throw usage_error("--components {} is outside 1..{} (the model's components)", a.components, full.components);
  const facefit::Model model = a.components > 0 ? facefit::truncated(full, static_cast<std::size_t>(a.components)) : full;
  const double ms_load = ms_since(t0);
  if (!a.full_shape.empty()) return run_full_shape(a, model);
  if (!a.batch.empty()) return run_batch(a, model, opt);

  if (a.space == Space::image && model.dims != 3) throw usage_error("--space image needs a 3-D model");
  const auto lm = load_landmarks(a, a.landmarks, model);
  const auto r = facefit::fit_landmarks(model, lm, opt);
  std::vector<double> sigma;
  if (!a.uncertainty.empty()) sigma = facefit::vertex_uncertainty(model, r, resolve_threads(a.threads));
  // Everything is computed (the textured mesh too) before the first byte is written.
  const Eigen::VectorXd shape_out = a.space == Space::image ? facefit::to_image_space(r.camera, r.shape) : r.shape;
  std::size_t visible = 0;
  std::optional<Mesh> textured;
  if (!a.texture.empty()) {
    if (model.dims != 3 || model.triangles.empty()) throw usage_error("--texture needs a 3-D model with triangles");
    textured = textured_mesh(a.texture, model, r, shape_out, &visible);
  }
  t0 = SteadyClock::now();
  if (!a.coeffs.empty()) write_output(a.coeffs, coeffs_tsv(r, model));
  if (!a.uncertainty.empty()) {
    std::string text = "vertex\tsigma\n";
    for (std::size_t j = 0; j < sigma.size(); ++j) text += fmt::format("{}\t{:.6g}\n", j, sigma[j]);
    write_output(a.uncertainty, text);
  }
  if (textured)
    write_mesh_to(*textured, a.output, a.to);
  else
    write_shape(shape_out, model.dims, model.triangles, a.output, a.to);
  if (!a.report.empty()) {
    nlohmann::json j = report_of(r, lm, model);
    if (!a.texture.empty()) j["texture"] = {{"file", a.texture}, {"visible_vertices", visible}};
    j["timings_ms"] = {{"load", ms_load}, {"build_Q", r.ms_build_q}, {"svd", r.ms_svd}, {"reconstruct", r.ms_reconstruct},
                       {"write", ms_since(t0)}};
    write_output(a.report, formats::write_json(j));
  }
  return 0;
}

Eta parse_eta(const std::string& text) {
  Eta e;
  if (text == "auto=gcv") {
    e.rule = Eta::Rule::gcv;
  } else if (text == "auto=evidence") {
    e.rule = Eta::Rule::evidence;
  } else {
    char* end = nullptr;
    e.value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(e.value) || e.value < 0)
      throw usage_error("--eta must be a number >= 0, auto=gcv or auto=evidence, not '{}'", text);
  }
  return e;
}

}  // namespace fest::facefit_tool
