// resample metrics: error against a reference and zone-plate aliasing, as one JSON object.
#include <cmath>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "core/file_io.hpp"
#include "image_files.hpp"
#include "sampling/float_image.hpp"
#include "sampling/image_metrics.hpp"
#include "sampling/kernel_params.hpp"
#include "sampling/srgb.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

// The values compared: linear light (integers sRGB-decoded) or the encoded values
// (integers as code / max, floats sRGB-encoded). Alpha is never premultiplied here.
FloatImage values(const Image& img, bool linear) {
  Encoding enc;
  enc.decode_srgb = linear && img.color_space == ColorSpace::srgb && img.pixels.depth() != CV_32F;
  FloatImage f = to_working(img, enc);
  if (!linear && img.pixels.depth() == CV_32F)
    for (auto& v : f.data) v = linear_to_srgb(v);
  return f;
}

nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

void check_metrics_args(const MetricsArgs& a, bool zoneplate) {
  if (a.ref.empty() && !zoneplate && !a.spectrum && a.beat.empty())
    throw usage_error("metrics needs --ref, --zoneplate, --spectrum or --beat");
  if (!a.beat.empty() && (a.beat.size() != 2 || !std::isfinite(a.beat[0]) || !std::isfinite(a.beat[1])))
    throw usage_error("--beat takes f1,f2");
  if (a.alias_band.size() != 2 || a.pass_band.size() != 2) throw usage_error("a band is lo,hi");
}

int run_metrics(const MetricsArgs& a) {
  check_metrics_args(a, a.zoneplate.has_value());
  const bool linear = a.domain == MetricsDomain::linear;

  const LoadedImage test = load_image(a.input);
  const FloatImage t = values(test.image, linear);
  nlohmann::json j = nlohmann::json::object();
  j["n_pixels"] = static_cast<long long>(t.width) * t.height;
  if (!a.ref.empty()) {
    const LoadedImage ref = load_image(a.ref);
    std::vector<std::uint8_t> mask;
    if (!a.mask.empty()) {
      const LoadedImage m = load_image(a.mask);
      if (m.image.pixels.channels() != 1) throw bad_input("--mask must be a one-channel image ({})", a.mask);
      cv::Mat nonzero = m.image.pixels != 0;
      mask.assign(nonzero.datastart, nonzero.dataend);
    }
    const ErrorMeasures e = compare_images(t, values(ref.image, linear), mask);
    j["rmse"] = e.rmse;
    j["psnr"] = json_number(e.psnr);
    j["maxabs"] = e.maxabs;
    j["n_pixels"] = e.n_pixels;
  }
  if (a.zoneplate) {
    const int w = a.zoneplate->width, h = a.zoneplate->height;
    if ((w > 0 && w != t.width) || (h > 0 && h != t.height))
      throw bad_input("metrics --zoneplate: the image is {}x{}, the scene {}x{}", t.width, t.height, w, h);
    const ZonePlateMeasures z = with_rewording({{"zone plate:", "metrics --zoneplate:"}}, [&] {
      return zoneplate_measures(t, a.zoneplate->numax, {a.alias_band[0], a.alias_band[1]}, {a.pass_band[0], a.pass_band[1]});
    });
    j["ae"] = z.ae;
    j["pr"] = z.pr;
    j["n_alias"] = z.n_alias;
    j["n_pass"] = z.n_pass;
  }
  if (a.spectrum || !a.beat.empty()) {
    const std::vector<double> power =
        with_rewording({{"power spectrum:", "metrics --spectrum:"}}, [&] { return row_power_spectrum(t); });
    if (a.spectrum) {
      std::vector<double> f(power.size());
      for (std::size_t k = 0; k < f.size(); ++k) f[k] = static_cast<double>(k) / t.width;
      j["spectrum"] = {{"f", f}, {"power", power}};
    }
    if (!a.beat.empty()) {
      const double df = std::fabs(a.beat[0] - a.beat[1]);
      const auto k = static_cast<std::size_t>(std::lround(df * t.width));
      if (k >= power.size()) throw usage_error("--beat: |f1 - f2| = {} is beyond the Nyquist frequency", df);
      j["beat_frequency"] = static_cast<double>(k) / t.width;
      j["beat_power"] = power[k];
    }
  }
  write_output("-", j.dump() + "\n");
  return 0;
}

}  // namespace fest::resample_tool
