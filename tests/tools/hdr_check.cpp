// Test tooling for hdrmerge's CLI tests (not installed): makes a known radiance image
// and measures results against the mathematics, so the shell tests need no Python.
//
//   hdr_check ramp W H OUT.pfm        radiance E = 10^(-2 + 4 u), u a ramp in x with a
//                                     ripple in y; channels scaled 1, 0.8, 0.6
//   hdr_check logrms MERGED TRUTH [VALID MIN]
//                                     "rms offset used_fraction": RMS of ln(merged/truth)
//                                     minus its mean, over samples finite and > 0 (and
//                                     whose validity map value is at least MIN)
//   hdr_check curve RESPONSE.csv G    worst |exp(g(z) - G ln(z/128)) - 1| over z 10..245

#include <cmath>
#include <cstdio>
#include <string>

#include "core/file_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace {

cv::Mat load(const std::string& path) {
  return fest::formats::parse(fest::formats::load_input(path), fest::formats::read_image).pixels;
}

int ramp(int w, int h, const std::string& out) {
  cv::Mat e(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = std::fmin(1.0, std::fmax(0.0, (x + 0.5) / w + 0.05 * std::sin(6.283185307179586 * y / h)));
      for (int c = 0; c < 3; ++c) e.ptr<float>(y)[x * 3 + c] = float(std::pow(10.0, -2.0 + 4.0 * u) * (1.0 - 0.2 * c));
    }
  fest::write_output(out, fest::formats::write_image(fest::Image{e, fest::ColorSpace::linear}, fest::formats::Format::pfm));
  return 0;
}

int logrms(const std::string& merged_path, const std::string& truth_path, const std::string& valid_path,
           double min_valid) {
  const cv::Mat m = load(merged_path), t = load(truth_path);
  const cv::Mat v = valid_path.empty() ? cv::Mat() : load(valid_path);
  if (m.size() != t.size() || m.channels() != t.channels()) return std::fprintf(stderr, "size mismatch\n"), 1;
  const std::size_t n = m.total() * std::size_t(m.channels());
  double sum = 0, sum2 = 0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = m.ptr<float>()[i], b = t.ptr<float>()[i];
    if (!(a > 0 && std::isfinite(a) && b > 0)) continue;
    if (!v.empty() && !(v.ptr<float>()[i / std::size_t(m.channels())] >= min_valid)) continue;
    const double d = std::log(a / b);
    sum += d;
    sum2 += d * d;
    ++used;
  }
  const double mean = sum / double(used);
  std::printf("%.6f %.6f %.6f\n", std::sqrt(std::fmax(0.0, sum2 / double(used) - mean * mean)), mean,
              double(used) / double(n));
  return 0;
}

int curve(const std::string& path, double gamma) {
  const fest::Table t = fest::formats::parse(fest::formats::load_input(path), fest::formats::read_table);
  double worst = 0;
  for (std::size_t c = 1; c < t.cols(); ++c)
    for (int z = 10; z <= 245; ++z)
      worst = std::fmax(worst, std::fabs(std::expm1(t.columns[c][std::size_t(z)] - gamma * std::log(z / 128.0))));
  std::printf("%.6f\n", worst);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "ramp" && argc == 5) return ramp(std::stoi(argv[2]), std::stoi(argv[3]), argv[4]);
    if (mode == "logrms" && argc == 4) return logrms(argv[2], argv[3], "", 0);
    if (mode == "logrms" && argc == 6) return logrms(argv[2], argv[3], argv[4], std::stod(argv[5]));
    if (mode == "curve" && argc == 4) return curve(argv[2], std::stod(argv[3]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hdr_check: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: hdr_check ramp W H OUT | logrms MERGED TRUTH | curve CSV GAMMA\n");
  return 2;
}
