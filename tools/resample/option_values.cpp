// The spellings of resample's enumerated flags -> their types (commands.hpp), each a usage
// error naming the flag and the choices when it is none of them.

#include "commands.hpp"
#include "core/error.hpp"

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

}  // namespace fest::resample
