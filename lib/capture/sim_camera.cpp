#include "capture/sim_camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>

#include "capture/frames.hpp"
#include "capture/json_fields.hpp"
#include "capture/sim_turntable.hpp"
#include "core/error.hpp"

namespace fest::capture {

using nlohmann::json;
using reflectance::LafortuneBrdf;
using reflectance::LafortuneLobe;
using reflectance::Rgb;

double SimResponse::curve(double x) const {
  if (!(x > 0)) return 0;
  double v = x >= toe ? std::pow(x, 1 / gamma) : x * std::pow(toe, 1 / gamma - 1);
  if (v > shoulder) v = shoulder + (1 - shoulder) * (1 - std::exp(-(v - shoulder) / (1 - shoulder)));
  return v;
}

double SimResponse::dn(double x) const {
  const double full = std::ldexp(1.0, bits) - 1;
  return black_level + (full - black_level) * curve(x);
}

SimScene default_sim_scene() {
  SimScene s;
  LafortuneBrdf glossy;
  glossy.rho_d = Rgb(0.1, 0.15, 0.5);
  LafortuneLobe lobe;
  lobe.cxy = Rgb::Constant(-1);
  lobe.cz = Rgb::Constant(1);
  lobe.n = Rgb::Constant(30);
  glossy.lobes = {lobe};
  s.materials = {reflectance::clay(), glossy};
  return s;
}

LafortuneBrdf parse_lafortune(const json& doc, const std::string& where, const std::string& path) {
  const JsonFields f(where);
  f.keys(doc, path, {"model", "lobes", "rho_d", "Cxy", "Cz", "N"});
  if (doc.contains("model") && doc["model"] != "lafortune") f.fail("must be \"lafortune\"", json_path(path, "model"));
  if (!doc.contains("rho_d")) f.fail("missing", json_path(path, "rho_d"));
  LafortuneBrdf b;
  const std::array<double, 3> rho = f.vec3(doc["rho_d"], json_path(path, "rho_d"));
  b.rho_d = Rgb(rho[0], rho[1], rho[2]);
  auto rows = [&](const char* key) {
    std::vector<Rgb> out;
    if (!doc.contains(key)) return out;
    const std::string p = json_path(path, key);
    if (!doc[key].is_array()) f.fail("must be an array of [r,g,b] per lobe", p);
    for (std::size_t i = 0; i < doc[key].size(); ++i) {
      const std::array<double, 3> v = f.vec3(doc[key][i], fmt::format("{}[{}]", p, i));
      out.emplace_back(v[0], v[1], v[2]);
    }
    return out;
  };
  const std::vector<Rgb> cxy = rows("Cxy"), cz = rows("Cz"), n = rows("N");
  if (cxy.size() != cz.size() || cxy.size() != n.size()) f.fail("Cxy, Cz and N must have one row per lobe", path);
  if (doc.contains("lobes") && f.integer(doc["lobes"], json_path(path, "lobes"), 0, 16) != int(cxy.size()))
    f.fail("does not match the rows of Cxy", json_path(path, "lobes"));
  for (std::size_t i = 0; i < cxy.size(); ++i) {
    if ((n[i].array() <= 0).any()) f.fail("exponents must be positive", fmt::format("{}[{}]", json_path(path, "N"), i));
    b.lobes.push_back({cxy[i], cz[i], n[i]});
  }
  return b;
}

SimScene parse_sim_scene(const json& doc, const std::string& where) {
  const JsonFields f(where);
  f.keys(doc, "", {"width", "height", "object", "gain", "backlight_radiance", "response", "seed"});
  SimScene s = default_sim_scene();
  if (doc.contains("width")) s.width = f.integer(doc["width"], "width", 8, 1 << 14);
  if (doc.contains("height")) s.height = f.integer(doc["height"], "height", 8, 1 << 14);
  if (doc.contains("object")) {
    const json& o = doc["object"];
    f.keys(o, "object", {"shape", "centre_mm", "radius_mm", "materials"});
    if (o.contains("shape") && o["shape"] != "sphere") f.fail("must be \"sphere\"", "object.shape");
    if (o.contains("centre_mm")) s.centre_mm = f.vec3(o["centre_mm"], "object.centre_mm");
    if (o.contains("radius_mm")) s.radius_mm = f.positive(o["radius_mm"], "object.radius_mm");
    if (o.contains("materials")) {
      const json& m = o["materials"];
      if (!m.is_array() || m.empty() || m.size() > 2) f.fail("must be an array of 1 or 2 brdf.json objects", "object.materials");
      s.materials.clear();
      for (std::size_t i = 0; i < m.size(); ++i)
        s.materials.push_back(parse_lafortune(m[i], where, fmt::format("object.materials[{}]", i)));
    }
  }
  if (doc.contains("gain")) s.gain = f.positive(doc["gain"], "gain");
  if (doc.contains("backlight_radiance")) s.backlight_radiance = f.number(doc["backlight_radiance"], "backlight_radiance", 0, 1e12);
  if (doc.contains("response")) {
    const json& r = doc["response"];
    f.keys(r, "response", {"bits", "gamma", "toe", "shoulder", "black_level", "noise_dn"});
    if (r.contains("bits")) {
      s.response.bits = f.integer(r["bits"], "response.bits", 8, 16);
      if (s.response.bits != 8 && s.response.bits != 16) f.fail("must be 8 or 16", "response.bits");
    }
    if (r.contains("gamma")) s.response.gamma = f.number(r["gamma"], "response.gamma", 0.2, 10);
    if (r.contains("toe")) s.response.toe = f.number(r["toe"], "response.toe", 1e-9, 0.5);
    if (r.contains("shoulder")) s.response.shoulder = f.number(r["shoulder"], "response.shoulder", 0.1, 0.999);
    if (r.contains("black_level")) s.response.black_level = f.number(r["black_level"], "response.black_level", 0, 4096);
    if (r.contains("noise_dn")) s.response.noise_dn = f.number(r["noise_dn"], "response.noise_dn", 0, 1e4);
  }
  if (doc.contains("seed")) s.seed = std::uint64_t(f.integer(doc["seed"], "seed", 0, 1 << 30));
  return s;
}

namespace {

Eigen::Matrix3d row_major(const std::array<double, 9>& m) {
  Eigen::Matrix3d r;
  r << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  return r;
}

struct PointLight {
  Eigen::Vector3d position;  // in T, mm
  Rgb intensity;
};

}  // namespace

cv::Mat render_sim_radiance(const SimScene& scene, const CameraIntrinsics& k, const TurntableCal& cal, double theta_deg,
                            const Station& station, const std::vector<std::string>& lights_on) {
  // C -> T: X_T = Rz(-theta) R_T0^T (X_C - t_T0).
  const Eigen::Matrix3d to_t = rotation_about_axis(-theta_deg) * row_major(cal.R_T0).transpose();
  const Eigen::Vector3d t0(cal.t_T0[0], cal.t_T0[1], cal.t_T0[2]);
  std::vector<PointLight> points;
  Rgb background = Rgb::Zero();
  for (const std::string& id : lights_on) {
    const LightConfig* l = station.light(id);
    if (!l) throw bad_input("sim camera: light \"{}\" is not in the station", id);
    const Rgb intensity(l->intensity[0], l->intensity[1], l->intensity[2]);
    if (l->role == "backlight") {
      background += scene.backlight_radiance * intensity;
      continue;
    }
    if (!l->position_mm) throw bad_input("sim camera: light \"{}\" needs position_mm (station)", id);
    const Eigen::Vector3d q((*l->position_mm)[0], (*l->position_mm)[1], (*l->position_mm)[2]);
    points.push_back({to_t * (q - t0), intensity});
  }
  const Eigen::Vector3d origin = to_t * (-t0);  // the camera centre in T
  const Eigen::Vector3d centre(scene.centre_mm[0], scene.centre_mm[1], scene.centre_mm[2]);
  const double r = scene.radius_mm;
  const Eigen::Vector3d oc = origin - centre;
  const double c_term = oc.squaredNorm() - r * r;

  cv::Mat out(k.height, k.width, CV_32FC3);
  const double fx = k.K[0], cx = k.K[2], fy = k.K[4], cy = k.K[5];
  cv::parallel_for_(cv::Range(0, k.height), [&](const cv::Range& rows) {
  for (int y = rows.start; y < rows.end; ++y) {
    float* row = out.ptr<float>(y);
    for (int x = 0; x < k.width; ++x) {
      const Eigen::Vector3d d = (to_t * Eigen::Vector3d((x - cx) / fx, (y - cy) / fy, 1.0)).normalized();
      const double b = d.dot(oc), disc = b * b - c_term;
      Rgb radiance = background;
      if (disc > 0 && -b - std::sqrt(disc) > 0) {
        const Eigen::Vector3d p = origin + (-b - std::sqrt(disc)) * d;
        const Eigen::Vector3d n = (p - centre) / r;
        const LafortuneBrdf& m = scene.materials[scene.materials.size() > 1 && p.x() < centre.x() ? 1 : 0];
        const Eigen::Matrix3d frame = reflectance::local_frame(n);
        const Eigen::Vector3d v_local = frame.transpose() * (-d);
        radiance = Rgb::Zero();
        for (const PointLight& l : points) {
          Eigen::Vector3d u = l.position - p;
          const double dist_m = u.norm() / 1000.0;
          u.normalize();
          const double cos_i = n.dot(u);
          if (cos_i <= 0) continue;
          const Rgb f = reflectance::evaluate(m, frame.transpose() * u, v_local);
          radiance += f.cwiseProduct(l.intensity) * (cos_i / (dist_m * dist_m));
        }
      }
      for (int c = 0; c < 3; ++c) row[3 * x + c] = float(radiance[c]);
    }
  }
  });  // rows are independent: the same bytes for any number of threads
  return out;
}

SimCamera::SimCamera(SimScene scene, CameraIntrinsics intrinsics, TurntableCal cal, Station station, Turntable& table,
                     LightBank& lights)
    : scene_(std::move(scene)),
      intrinsics_(intrinsics),
      cal_(cal),
      station_(std::move(station)),
      table_(table),
      lights_(lights) {
  if (scene_.materials.empty()) throw bad_input("sim camera: the scene has no material");
  steps_per_rev_ = table_.info().steps_per_rev;
}

CameraInfo SimCamera::info() {
  CameraInfo i;
  i.width = intrinsics_.width;
  i.height = intrinsics_.height;
  i.channels = 3;
  i.bits = scene_.response.bits;
  i.name = "fest sim camera";
  return i;
}

void SimCamera::set_exposure(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) throw usage_error("sim camera: exposure {} s must be positive", seconds);
  exposure_s_ = seconds;
}

double SimCamera::table_angle_deg() {
  if (auto* sim = dynamic_cast<SimTurntable*>(&table_)) return sim->table_position() * 360.0 / steps_per_rev_;
  return table_.status().position * 360.0 / steps_per_rev_;
}

cv::Mat SimCamera::expose(const cv::Mat& radiance, double seconds, std::uint64_t seed) const {
  const SimResponse& r = scene_.response;
  const double full = std::ldexp(1.0, r.bits) - 1;
  cv::Mat noise(radiance.size(), CV_32FC3);
  cv::RNG rng(seed);
  if (r.noise_dn > 0) rng.fill(noise, cv::RNG::NORMAL, 0.0, r.noise_dn);
  else noise.setTo(0);
  cv::Mat z(radiance.size(), r.bits == 16 ? CV_16UC3 : CV_8UC3);
  const double scale = scene_.gain * seconds;
  const double dark = r.dn(0);
  // Rows are independent (the noise is drawn above, in one sequence), so they are
  // exposed in parallel with the same bytes for any number of threads.
  cv::parallel_for_(cv::Range(0, radiance.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* in = radiance.ptr<float>(y);
      const float* n = noise.ptr<float>(y);
      for (int i = 0; i < 3 * radiance.cols; ++i) {
        const double dn = (in[i] > 0 ? r.dn(in[i] * scale) : dark) + n[i];
        // Round half up after the clamp (non-negative): cheaper than std::round.
        const double v = std::floor(std::clamp(dn, 0.0, full) + 0.5);
        if (r.bits == 16) z.ptr<std::uint16_t>(y)[i] = std::uint16_t(v);
        else z.ptr<std::uint8_t>(y)[i] = std::uint8_t(v);
      }
    }
  });
  return z;
}

Image SimCamera::capture() {
  const double theta = table_angle_deg();
  std::vector<std::string> on;
  for (const LightState& l : lights_.list())
    if (l.on) on.push_back(l.id);
  std::string key = fmt::format("{:.9f}", theta);
  for (const std::string& id : on) key += "|" + id;
  if (key != cache_key_ || cache_.empty()) {
    cache_ = render_sim_radiance(scene_, intrinsics_, cal_, theta, station_, on);
    cache_key_ = key;
  }
  // The noise seed is a function of what is photographed (FNV-1a of the state), never of
  // how many pictures came before: a resumed session re-creates the same bytes.
  std::uint64_t h = 1469598103934665603ull ^ scene_.seed;
  // Repeated takes of one exposure (take > 0) get noise of their own.
  const std::string state = key + fmt::format("|{:.9g}", exposure_s_) + (take_ > 0 ? fmt::format("|take {}", take_) : "");
  for (unsigned char ch : state) h = (h ^ ch) * 1099511628211ull;
  return Image{expose(cache_, exposure_s_, h), ColorSpace::srgb};
}

}  // namespace fest::capture
