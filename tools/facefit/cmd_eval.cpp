// facefit eval: the per-vertex 3-D error of an estimate against the truth, and its picture.

#include <sys/stat.h>

#include <cmath>
#include <map>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "commands.hpp"
#include "face_files.hpp"
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

}  // namespace fest::facefit_tool
