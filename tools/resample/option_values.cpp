// The spellings of resample's enumerated flags -> their types (commands.hpp), each a usage
// error naming the flag and the choices when it is none of them.

#include <cmath>
#include <cstdlib>

#include "commands.hpp"
#include "core/error.hpp"
#include "sampling/kernel_params.hpp"

namespace fest::resample {

using namespace fest::sampling;

EdgeMode parse_edge(const std::string& s) {
  if (s == "clamp") return EdgeMode::clamp;
  if (s == "reflect") return EdgeMode::reflect;
  if (s == "wrap") return EdgeMode::wrap;
  if (s == "zero") return EdgeMode::zero;
  throw usage_error("--edge: '{}' is not one of clamp, reflect, wrap, zero", s);
}

ClampMode parse_clamp(const std::string& s) {
  if (s == "auto") return ClampMode::automatic;
  if (s == "none") return ClampMode::none;
  if (s == "range") return ClampMode::range;
  if (s == "local") return ClampMode::local;
  throw usage_error("--clamp: '{}' is not one of none, range, local", s);
}

ResizeColor parse_resize_color(const std::string& s) {
  if (s == "auto") return ResizeColor::automatic;
  if (s == "srgb") return ResizeColor::srgb;
  if (s == "linear") return ResizeColor::linear;
  if (s == "codes") return ResizeColor::codes;
  throw usage_error("--colorspace: '{}' is not one of auto, srgb, linear, codes", s);
}

AlphaMode parse_alpha(const std::string& s) {
  if (s == "premul") return AlphaMode::premul;
  if (s == "straight") return AlphaMode::straight;
  if (s == "none") return AlphaMode::none;
  throw usage_error("--alpha: '{}' is not one of premul, straight, none", s);
}

MetricsDomain parse_metrics_domain(const std::string& s) {
  if (s == "linear") return MetricsDomain::linear;
  if (s == "encoded") return MetricsDomain::encoded;
  throw usage_error("--domain: '{}' is not linear or encoded", s);
}

MipFilter parse_mip_filter(const std::string& s) {
  if (s == "box") return MipFilter::box;
  if (s == "gaussian") return MipFilter::gaussian;
  if (s == "lanczos3") return MipFilter::lanczos3;
  throw usage_error("mip --filter: '{}' is not one of box, gaussian, lanczos3", s);
}

ZonePlate parse_zoneplate(const std::string& text) {
  const auto zp = parse_kernel_params("zoneplate", text, {{"numax", 1}, {"width", 0}, {"height", 0}});
  ZonePlate z;
  z.numax = zp.at("numax");
  z.width = static_cast<int>(zp.at("width"));
  z.height = static_cast<int>(zp.at("height"));
  return z;
}

RenderColor parse_render_color(const std::string& s) {
  if (s == "srgb") return RenderColor::srgb;
  if (s == "linear") return RenderColor::linear;
  throw usage_error("--colorspace: '{}' is not srgb or linear", s);
}

// --param k=v (repeatable; each may also hold k=v,k2=v2).
std::map<std::string, double> parse_params(const std::vector<std::string>& given) {
  std::map<std::string, double> out;
  for (const auto& g : given) {
    std::size_t start = 0;
    while (start <= g.size()) {
      const std::size_t comma = g.find(',', start);
      const std::string item = g.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      const auto eq = item.find('=');
      if (eq == std::string::npos || eq == 0) throw usage_error("--param: '{}' is not key=value", item);
      char* end = nullptr;
      const std::string value = item.substr(eq + 1);
      const double v = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !std::isfinite(v)) throw usage_error("--param: '{}' is not a number", item);
      out[item.substr(0, eq)] = v;
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

}  // namespace fest::resample
