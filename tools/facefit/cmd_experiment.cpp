// facefit synth / project / eval / sweep: the chapter's experiments, end to end.

#include <sys/stat.h>

#include <cmath>
#include <map>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/image.hpp"
#include "facefit/camera.hpp"
#include "facefit/evaluate.hpp"
#include "facefit/render.hpp"
#include "facefit/synth.hpp"
#include "formats/facemodel/landmarks_io.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

int run_synth(const SynthArgs& a) {
  if (a.output.empty()) throw usage_error("synth needs -o DIR");
  if (a.faces < 2 || a.train < 2 || a.train > a.faces) throw usage_error("need 2 <= --train <= --faces");
  if (a.resolution < 16 || a.resolution > 2048) throw usage_error("--resolution must be in 16..2048");
  if (!(a.detail >= 0)) throw usage_error("--detail-mm must be >= 0");
  if (::mkdir(a.output.c_str(), 0777) != 0 && errno != EEXIST) throw io_error("cannot create folder '{}'", a.output);
  facefit::Rng rng(a.seed);
  const auto tris = facefit::grid_triangles(a.resolution);
  std::string train, test;
  for (int i = 0; i < a.faces; ++i) {
    const auto face = facefit::draw_face(rng, a.detail);
    const std::string name = fmt::format("face{:03d}.ply", i + 1);
    write_mesh_to(shape_to_mesh(facefit::face_shape(face, a.resolution), 3, tris), a.output + "/" + name, "");
    (i < a.train ? train : test) += name + "\n";
  }
  write_output(a.output + "/train.txt", train);
  write_output(a.output + "/test.txt", test);
  const auto sets = facefit::synth_landmarks(a.resolution, a.seed);
  write_output(a.output + "/set17.tsv", formats::write_vertex_set(sets.set17));
  write_output(a.output + "/set50.tsv", formats::write_vertex_set(sets.set50));
  write_output(a.output + "/set1000.tsv", formats::write_vertex_set(sets.set1000));
  write_output(a.output + "/landmarks.tsv", formats::write_vertex_set(sets.set50));
  std::vector<facefit::NamedVertex> mask;
  for (auto v : sets.eval_mask) mask.push_back({std::to_string(v), v});
  write_output(a.output + "/evalmask.tsv", formats::write_vertex_set(mask));
  return 0;
}

int run_project(const ProjectArgs& a) {
  if (a.vertices.empty()) throw usage_error("project needs --vertices SET.tsv");
  if (a.noise_sigma < 0) throw usage_error("--noise-sigma must be >= 0");
  Eigen::VectorXd shape;
  if (!a.mesh.empty()) {
    shape = read_shape(a.mesh);
  } else {
    const facefit::Model m = load_model(a.model);
    if (m.dims != 3) throw bad_input("project needs a 3-D model");
    shape = Eigen::Map<const Eigen::VectorXd>(m.mean.data(), static_cast<Eigen::Index>(m.mean.size()));
  }
  const auto set = formats::read_vertex_set(read_text(a.vertices), a.vertices);
  const auto& c = a.center;
  const auto P = facefit::orthographic_camera(a.scale, {c[0], c[1]}, a.yaw, a.pitch);
  facefit::Rng rng(a.seed);
  std::vector<facefit::LandmarkEntry> out;
  for (const auto& nv : set) {
    if (3 * static_cast<Eigen::Index>(nv.vertex) + 2 >= shape.size())
      throw bad_input("vertex {} of '{}' is out of range ({} vertices)", nv.vertex, nv.name, shape.size() / 3);
    const Eigen::Vector3d x = shape.segment<3>(3 * static_cast<Eigen::Index>(nv.vertex));
    Eigen::Vector2d uv = P.leftCols<3>() * x + P.col(3);
    if (a.noise_sigma > 0) {
      uv.x() += a.noise_sigma * rng.normal();
      uv.y() += a.noise_sigma * rng.normal();
    }
    facefit::LandmarkEntry e;
    e.id = nv.name;
    e.by_vertex = a.by_vertex;
    e.vertex = nv.vertex;
    e.u = uv.x();
    e.v = uv.y();
    out.push_back(e);
  }
  write_output("-", formats::write_landmarks(out));
  return 0;
}

namespace {

// Three panels side by side: truth shaded, estimate shaded, error colour-mapped
// (0 .. max error, blue to red) over the estimate's shading.
void write_error_png(const std::string& path, const Eigen::VectorXd& truth, const Eigen::VectorXd& estimate,
                     const std::vector<std::array<std::uint32_t, 3>>& tris, const std::vector<double>& err) {
  // Frame the truth's bounding box in a 300-pixel-high panel.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for (Eigen::Index j = 0; j < truth.size() / 3; ++j) {
    lo = lo.cwiseMin(truth.segment<3>(3 * j));
    hi = hi.cwiseMax(truth.segment<3>(3 * j));
  }
  const int H = 300;
  const double scale = 0.9 * H / std::max({hi.y() - lo.y(), hi.x() - lo.x(), 1e-9});
  const int W = std::max(32, static_cast<int>(std::ceil((hi.x() - lo.x()) * scale / 0.9)));
  const Eigen::Vector2d center(W / 2.0 - scale * (lo.x() + hi.x()) / 2, H / 2.0 + scale * (lo.y() + hi.y()) / 2);
  const auto rt = facefit::rasterise(truth, tris, {}, W, H, scale, center);
  const auto re = facefit::rasterise(estimate, tris, err, W, H, scale, center);
  double emax = 0;
  for (double e : err) emax = std::max(emax, e);
  cv::Mat grey(H, W, CV_8UC1), heat(H, W, CV_8UC1), mask(H, W, CV_8UC1);
  cv::Mat out(H, 3 * W, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
      const auto g = [](float s) { return cv::Vec3b::all(static_cast<unsigned char>(40 + 215 * s)); };
      if (rt.shading[i] > 0 || !std::isnan(rt.value[i])) out.at<cv::Vec3b>(y, x) = g(rt.shading[i]);
      if (!std::isnan(re.value[i])) out.at<cv::Vec3b>(y, W + x) = g(re.shading[i]);
      heat.at<unsigned char>(y, x) = static_cast<unsigned char>(emax > 0 ? std::clamp(255.0 * re.value[i] / emax, 0.0, 255.0) : 0);
      mask.at<unsigned char>(y, x) = std::isnan(re.value[i]) ? 0 : 255;
      grey.at<unsigned char>(y, x) = static_cast<unsigned char>(80 + 175 * re.shading[i]);
    }
  cv::Mat colour;
  cv::applyColorMap(heat, colour, cv::COLORMAP_JET);  // BGR
  cv::cvtColor(colour, colour, cv::COLOR_BGR2RGB);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (mask.at<unsigned char>(y, x)) {
        const double s = grey.at<unsigned char>(y, x) / 255.0;
        cv::Vec3b c = colour.at<cv::Vec3b>(y, x);
        for (int ch = 0; ch < 3; ++ch) c[ch] = static_cast<unsigned char>(c[ch] * s);
        out.at<cv::Vec3b>(y, 2 * W + x) = c;
      }
  Image img;
  img.pixels = out;
  formats::store_output(path, formats::write_image(img, formats::Format::png), false);
}

}  // namespace

int run_eval(const EvalArgs& a) {
  std::vector<std::array<std::uint32_t, 3>> tris;
  const Eigen::VectorXd truth = read_shape(a.truth, &tris);
  const Eigen::VectorXd est = read_shape(a.estimate);
  if (truth.size() != est.size())
    throw bad_input("truth has {} vertices, estimate {}: not in correspondence", truth.size() / 3, est.size() / 3);
  const auto err = facefit::vertex_errors(est, truth, 3);
  std::vector<std::uint32_t> mask;
  if (!a.mask.empty()) mask = read_vertex_indices(a.mask);
  double rms = 0, mx = 0;
  const std::size_t count = mask.empty() ? err.size() : mask.size();
  for (std::size_t i = 0; i < count; ++i) {
    const double e = err[mask.empty() ? i : mask[i]];
    rms += e * e;
    mx = std::max(mx, e);
  }
  std::string text;
  if (a.per_vertex) {
    text = "vertex\terror\n";
    for (std::size_t j = 0; j < err.size(); ++j) text += fmt::format("{}\t{:.9g}\n", j, err[j]);
  } else {
    text = fmt::format("vertices\tE_full\trms\tmax\n{}\t{:.9g}\t{:.9g}\t{:.9g}\n", count, facefit::mean_error(err, mask),
                       std::sqrt(rms / static_cast<double>(count)), mx);
  }
  if (!a.png.empty()) write_error_png(a.png, truth, est, tris, err);
  write_output(a.output, text);
  return 0;
}

int run_sweep(const SweepArgs& a) {
  const facefit::Model model = load_model(a.model);
  if (a.faces.empty() || a.vertices.empty()) throw usage_error("sweep needs --faces LIST and --vertices SET.tsv");
  std::vector<Eigen::VectorXd> faces;
  for (const auto& p : read_list(a.faces)) faces.push_back(read_shape(p));
  const auto vertices = read_vertex_indices(a.vertices);
  const auto& etas = a.etas;
  for (double e : etas)
    if (e < 0) throw usage_error("--etas: η must be >= 0");
  std::vector<double> comps = a.components.empty() ? std::vector<double>{static_cast<double>(model.components)}
                                                   : a.components;
  const auto& noises = a.noise;
  const auto& yaws = a.yaw;
  std::vector<facefit::SweepSetting> settings;
  for (double k : comps) {
    if (k < 1 || k > static_cast<double>(model.components) || k != std::floor(k))
      throw usage_error("--components {} outside 1..{}", k, model.components);
    for (double s : noises) {
      if (s < 0) throw usage_error("--noise-sigma must be >= 0");
      for (double y : yaws) settings.push_back({static_cast<std::size_t>(k), s, y});
    }
  }
  const std::vector<std::uint32_t> mask = a.mask.empty() ? model.eval_mask : read_vertex_indices(a.mask);
  const auto rows = facefit::sweep(model, faces, vertices, etas, settings, mask, a.seed);
  std::string text;
  if (!a.summary) {
    text = "face\tcomponents\tf\teta\tsigma_N\tyaw_deg\tE_r\tE_r_rms\tnorm_c\tE_full\n";
    for (const auto& r : rows)
      text += fmt::format("{}\t{}\t{}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\n", r.face, r.setting.components, r.f,
                          r.eta, r.setting.sigma_noise, r.setting.yaw_deg, r.E_r, r.E_r_rms, r.norm_c, r.E_full);
  } else {
    // Means over faces per (setting, η): the paper's curves. Row order: settings, then η.
    struct Acc { double E_r = 0, E_r_rms = 0, norm_c = 0, E_full = 0; std::size_t n = 0; };
    std::vector<Acc> acc(settings.size() * etas.size());
    std::size_t i = 0;
    for (const auto& r : rows) {
      auto& s = acc[i++ % acc.size()];
      s.E_r += r.E_r; s.E_r_rms += r.E_r_rms; s.norm_c += r.norm_c; s.E_full += r.E_full; ++s.n;
    }
    text = "components\tf\teta\tsigma_N\tyaw_deg\tE_r\tE_r_rms\tnorm_c\tE_full\n";
    for (std::size_t si = 0; si < settings.size(); ++si)
      for (std::size_t ei = 0; ei < etas.size(); ++ei) {
        const auto& s = acc[si * etas.size() + ei];
        const double n = static_cast<double>(s.n);
        text += fmt::format("{}\t{}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\n", settings[si].components, vertices.size(),
                            etas[ei], settings[si].sigma_noise, settings[si].yaw_deg, s.E_r / n, s.E_r_rms / n, s.norm_c / n, s.E_full / n);
      }
  }
  write_output("-", text);
  return 0;
}

}  // namespace fest::facefit_tool
