#include "sampling/scenes.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sampling/kernel_params.hpp"

namespace fest::sampling {

namespace {

constexpr double pi = 3.14159265358979323846;

// The parameters the user gave, checked against the scene's keys and defaults.
std::map<std::string, double> with_defaults(const std::string& scene, const std::map<std::string, double>& given,
                                            std::map<std::string, double> defaults) {
  for (const auto& [k, v] : given) {
    auto it = defaults.find(k);
    if (it == defaults.end()) {
      std::string keys;
      for (const auto& d : defaults) keys += (keys.empty() ? "" : ", ") + d.first;
      throw usage_error("scene '{}' has no parameter '{}' (known: {})", scene, k, keys);
    }
    if (!std::isfinite(v)) throw usage_error("scene '{}': parameter {} = {} is not finite", scene, k, v);
    it->second = v;
  }
  return defaults;
}

// Radial ideal low-pass of cut-off ρ (a disk of radius ρ in the frequency plane): its
// point spread is ρ J₁(2πρr)/r, with the limit πρ² at r = 0.
double radial_lowpass(double rho, double r) {
  if (r < 1e-9) return pi * rho * rho;
  return rho * std::cyl_bessel_j(1.0, 2 * pi * rho * r) / r;
}

}  // namespace

std::vector<std::string> scene_names() { return {"zoneplate", "sine", "siemens", "edges", "point", "checker-plane"}; }

double zoneplate_frequency(double numax, int width, int height, int i, int j) {
  const double dx = i + 0.5 - width / 2.0, dy = j + 0.5 - height / 2.0;
  return numax * std::sqrt(dx * dx + dy * dy) / (width / 2.0);
}

double zoneplate_value(double numax, int width, int height, double x, double y) {
  const double dx = x - width / 2.0, dy = y - height / 2.0;
  return 0.5 + 0.5 * std::cos(pi * numax * (dx * dx + dy * dy) / (width / 2.0));
}

Scene make_scene(const std::string& name, const std::map<std::string, double>& given, int width, int height,
                 const std::string& point_filter) {
  if (width <= 0 || height <= 0) throw usage_error("scene size {}x{} must be positive", width, height);
  Scene s;
  s.name = name;
  const double cx0 = width / 2.0, cy0 = height / 2.0;
  if (name == "zoneplate") {
    const auto p = with_defaults(name, given, {{"numax", 1.0}});
    const double numax = p.at("numax");
    s.value = [numax, width, height](double x, double y) { return zoneplate_value(numax, width, height, x, y); };
  } else if (name == "sine") {
    const auto p = with_defaults(name, given, {{"f", 0.1}, {"phase", 0}, {"angle", 0}, {"f2", -1}});
    const double f = p.at("f"), phase = p.at("phase"), f2 = p.at("f2");
    const double c = std::cos(p.at("angle") * pi / 180), sn = std::sin(p.at("angle") * pi / 180);
    if (f2 < 0) {
      s.value = [=](double x, double y) { return 0.5 + 0.5 * std::cos(2 * pi * f * (c * x + sn * y) + phase); };
    } else {
      // Two gratings of half contrast each: the beat pair of §10.4.4.
      s.value = [=](double x, double y) {
        const double t = c * x + sn * y;
        return 0.5 + 0.25 * std::cos(2 * pi * f * t + phase) + 0.25 * std::cos(2 * pi * f2 * t + phase);
      };
    }
  } else if (name == "siemens") {
    const auto p = with_defaults(name, given, {{"spokes", 64}});
    const double n = p.at("spokes");
    if (!(n >= 1 && n <= 1e6)) throw usage_error("scene 'siemens': spokes = {} is out of range [1, 1e6]", n);
    s.value = [=](double x, double y) { return std::sin(n * std::atan2(y - cy0, x - cx0)) > 0 ? 1.0 : 0.0; };
  } else if (name == "edges") {
    const double a23 = 23 * pi / 180;
    const auto p = with_defaults(name, given,
                                 {{"cx", 32.17}, {"cy", 31.61}, {"radius", 20.3}, {"angle", 23},
                                  {"offset", 40 * (std::cos(a23) + std::sin(a23))}});
    const double cx = p.at("cx"), cy = p.at("cy"), r = p.at("radius"), off = p.at("offset");
    const double nx = std::cos(p.at("angle") * pi / 180), ny = std::sin(p.at("angle") * pi / 180);
    s.value = [=](double x, double y) {
      const bool disk = (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r;
      const bool half = x * nx + y * ny < off;
      return disk != half ? 1.0 : 0.0;
    };
  } else if (name == "point") {
    const auto p = with_defaults(name, given, {{"w", 1}, {"x0", cx0}, {"y0", cy0}, {"zoom", 8}, {"lo", 0.2}});
    const double w = p.at("w"), x0 = p.at("x0"), y0 = p.at("y0"), zoom = p.at("zoom"), lo = p.at("lo");
    if (!(zoom > 0)) throw usage_error("scene 'point': zoom must be positive");
    s.analytic = true;
    constexpr double cutoff = 0.5;  // ρ_c: the Nyquist frequency of the filter's pixel grid
    std::function<double(double, double)> h;
    if (point_filter == "lowpass") {
      h = [](double u, double v) { return radial_lowpass(cutoff, std::hypot(u, v)); };
    } else if (point_filter == "bandpass") {
      if (!(lo > 0 && lo < 1)) throw usage_error("scene 'point': bandpass lo = {} is out of range (0, 1)", lo);
      // The annulus lo <= ρ < ρ₂ with ρ₂² − lo² = ρ_c²: the same spectral area as the
      // low-pass, so the same retained signal energy (the chapter's point, Fig. 10.7).
      const double rho2 = std::sqrt(cutoff * cutoff + lo * lo);
      h = [rho2, lo](double u, double v) {
        const double r = std::hypot(u, v);
        return radial_lowpass(rho2, r) - radial_lowpass(lo, r);
      };
    } else {
      const Kernel k = make_kernel(point_filter);
      if (!k.spatial || !std::isfinite(k.radius) || k.nearest)
        throw usage_error("scene 'point': pixel filter '{}' has no finite spatial form", point_filter);
      // Unit area, so the Dirac's weight w is preserved.
      double area = 0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) area += k.spatial(-k.radius + 2 * k.radius * (i + 0.5) / n);
      area *= 2 * k.radius / n;
      h = [k, area](double u, double v) { return k.spatial(u) * k.spatial(v) / (area * area); };
    }
    s.value = [=](double x, double y) { return 0.5 + w * h((x - x0) / zoom, (y - y0) / zoom); };
  } else if (name == "checker-plane") {
    // The chapter's "chequerboard pattern of any size" (§10.3.1): the plane z = 0 seen by a
    // pinhole camera at height h pitched down by `pitch` degrees, vertical field of view
    // `fov`; squares of side `square`; above the horizon 0.5.
    const auto p = with_defaults(name, given, {{"h", 1}, {"pitch", 15}, {"fov", 60}, {"square", 0.5}});
    const double h = p.at("h"), sq = p.at("square");
    if (!(h > 0) || !(sq > 0) || !(p.at("fov") > 0 && p.at("fov") < 180) || std::fabs(p.at("pitch")) >= 90)
      throw usage_error("scene 'checker-plane': need h > 0, square > 0, 0 < fov < 180, |pitch| < 90");
    const double tan_half = std::tan(p.at("fov") * pi / 360), aspect = static_cast<double>(width) / height;
    const double cp = std::cos(p.at("pitch") * pi / 180), sp = std::sin(p.at("pitch") * pi / 180);
    s.value = [=](double x, double y) {
      const double sx = (2 * x / width - 1) * tan_half * aspect, sy = (1 - 2 * y / height) * tan_half;
      const double dz = -sp + sy * cp;
      if (dz >= -1e-12) return 0.5;
      const double t = h / -dz;
      const long i = static_cast<long>(std::floor(t * sx / sq)), j = static_cast<long>(std::floor(t * (cp + sy * sp) / sq));
      return ((i + j) % 2 == 0) ? 1.0 : 0.0;
    };
  } else {
    std::string names;
    for (const auto& n : scene_names()) names += (names.empty() ? "" : ", ") + n;
    throw usage_error("unknown scene '{}' (known: {})", name, names);
  }
  return s;
}

}  // namespace fest::sampling
