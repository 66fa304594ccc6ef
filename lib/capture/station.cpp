#include "capture/station.hpp"

#include <nlohmann/json.hpp>

#include "capture/json_fields.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::capture {

using nlohmann::json;

const LightConfig* Station::light(const std::string& id) const {
  for (const LightConfig& l : lights)
    if (l.id == id) return &l;
  return nullptr;
}

CameraIntrinsics parse_intrinsics(const json& doc, const std::string& where) {
  const JsonFields f(where);
  if (!doc.is_object()) f.fail("must be a JSON object", "intrinsics");
  CameraIntrinsics k;
  if (!doc.contains("K")) f.fail("missing", "K");
  k.K = f.mat3(doc["K"], "K");
  if (!(k.K[0] > 0 && k.K[4] > 0)) f.fail("focal lengths K[0], K[4] must be positive", "K");
  if (doc.contains("dist")) {
    const std::vector<double> d = f.numbers(doc["dist"], "dist", 0);
    if (d.size() > 5) f.fail("must have at most 5 coefficients k1,k2,p1,p2,k3", "dist");
    for (std::size_t i = 0; i < d.size(); ++i) k.dist[i] = d[i];
  }
  if (!doc.contains("width") || !doc.contains("height")) f.fail("needs \"width\" and \"height\"", "intrinsics");
  k.width = f.integer(doc["width"], "width", 1, 1 << 16);
  k.height = f.integer(doc["height"], "height", 1, 1 << 16);
  return k;
}

TurntableCal parse_turntable_cal(const json& doc, const std::string& where) {
  const JsonFields f(where);
  if (!doc.is_object()) f.fail("must be a JSON object", "calibration");
  if (!doc.contains("R_T0") || !doc.contains("t_T0")) f.fail("needs \"R_T0\" and \"t_T0\"", "calibration");
  TurntableCal c;
  c.R_T0 = f.mat3(doc["R_T0"], "R_T0");
  c.t_T0 = f.vec3(doc["t_T0"], "t_T0");
  // A rotation: orthonormal rows (1e-6 allows for printed decimals).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += c.R_T0[std::size_t(3 * i + k)] * c.R_T0[std::size_t(3 * j + k)];
      if (std::abs(dot - (i == j ? 1.0 : 0.0)) > 1e-6) f.fail("is not a rotation matrix", "R_T0");
    }
  return c;
}

Station parse_station(const json& doc, const std::string& where) {
  const JsonFields f(where);
  f.keys(doc, "", {"camera", "turntable", "lights"});
  Station s;
  if (!doc.contains("camera")) f.fail("missing", "camera");
  if (!doc.contains("turntable")) f.fail("missing", "turntable");
  if (!doc.contains("lights")) f.fail("missing", "lights");

  const json& c = doc["camera"];
  f.keys(c, "camera", {"uri", "intrinsics", "flush_frames", "format", "png_compression"});
  if (!c.contains("uri")) f.fail("missing", "camera.uri");
  s.camera.uri = f.string(c["uri"], "camera.uri");
  if (c.contains("intrinsics")) {
    if (c["intrinsics"].is_string()) s.camera.intrinsics_file = f.string(c["intrinsics"], "camera.intrinsics");
    else s.camera.intrinsics = parse_intrinsics(c["intrinsics"], where + ": camera.intrinsics");
  }
  if (c.contains("flush_frames")) s.camera.flush_frames = f.integer(c["flush_frames"], "camera.flush_frames", 0, 100);
  if (c.contains("png_compression")) s.camera.png_compression = f.integer(c["png_compression"], "camera.png_compression", 0, 9);
  if (c.contains("format")) {
    s.camera.format = f.string(c["format"], "camera.format");
    if (s.camera.format != "png16" && s.camera.format != "png8" && s.camera.format != "tiff16" && s.camera.format != "jpeg")
      f.fail("must be png16, png8, tiff16 or jpeg", "camera.format");
  }

  const json& t = doc["turntable"];
  f.keys(t, "turntable", {"uri", "calibration", "approach", "backlash_deg", "settle_ms", "require_homed"});
  if (!t.contains("uri")) f.fail("missing", "turntable.uri");
  s.turntable.uri = f.string(t["uri"], "turntable.uri");
  if (t.contains("calibration")) {
    if (t["calibration"].is_string()) s.turntable.calibration_file = f.string(t["calibration"], "turntable.calibration");
    else s.turntable.calibration = parse_turntable_cal(t["calibration"], where + ": turntable.calibration");
  }
  if (t.contains("approach")) {
    const std::string a = f.string(t["approach"], "turntable.approach");
    if (a != "ccw" && a != "cw") f.fail("must be \"ccw\" or \"cw\"", "turntable.approach");
    s.turntable.approach = a == "ccw" ? Approach::ccw : Approach::cw;
  }
  if (t.contains("backlash_deg")) s.turntable.backlash_deg = f.number(t["backlash_deg"], "turntable.backlash_deg", 0, 90);
  if (t.contains("settle_ms")) s.turntable.settle_ms = unsigned(f.integer(t["settle_ms"], "turntable.settle_ms", 0, 600000));
  if (t.contains("require_homed")) s.turntable.require_homed = f.boolean(t["require_homed"], "turntable.require_homed");

  const json& ls = doc["lights"];
  if (!ls.is_array()) f.fail("must be an array", "lights");
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const std::string p = fmt::format("lights[{}]", i);
    f.keys(ls[i], p, {"id", "uri", "active_low", "position_mm", "intensity", "role", "warmup_ms", "max_on_s"});
    LightConfig l;
    if (!ls[i].contains("id")) f.fail("missing", p + ".id");
    if (!ls[i].contains("uri")) f.fail("missing", p + ".uri");
    l.id = f.string(ls[i]["id"], p + ".id");
    if (l.id.find_first_of("/\\ ,:") != std::string::npos || l.id == "." || l.id == "..")
      f.fail("must be a name without '/', spaces, commas or colons (it names folders)", p + ".id");
    if (s.light(l.id)) f.fail(fmt::format("names light \"{}\" twice", quoted_bytes(l.id)), p + ".id");
    l.uri = f.string(ls[i]["uri"], p + ".uri");
    if (ls[i].contains("active_low")) l.active_low = f.boolean(ls[i]["active_low"], p + ".active_low");
    if (ls[i].contains("position_mm")) l.position_mm = f.vec3(ls[i]["position_mm"], p + ".position_mm");
    if (ls[i].contains("intensity")) {
      l.intensity = f.vec3(ls[i]["intensity"], p + ".intensity");
      for (double v : l.intensity)
        if (v < 0) f.fail("must not be negative", p + ".intensity");
    }
    if (ls[i].contains("role")) {
      l.role = f.string(ls[i]["role"], p + ".role");
      if (l.role != "light" && l.role != "backlight") f.fail("must be \"light\" or \"backlight\"", p + ".role");
    }
    if (ls[i].contains("warmup_ms")) l.warmup_ms = unsigned(f.integer(ls[i]["warmup_ms"], p + ".warmup_ms", 0, 600000));
    if (ls[i].contains("max_on_s")) l.max_on_s = f.number(ls[i]["max_on_s"], p + ".max_on_s", 0, 1e7);
    s.lights.push_back(l);
  }
  return s;
}

CameraIntrinsics default_intrinsics(int width, int height) {
  CameraIntrinsics k;
  const double focal = 1000.0 * width / 640.0;
  k.K = {focal, 0, (width - 1) / 2.0, 0, focal, (height - 1) / 2.0, 0, 0, 1};
  k.width = width;
  k.height = height;
  return k;
}

TurntableCal default_turntable_cal() {
  TurntableCal c;
  // Columns are T's axes in C: x_T = (1,0,0), y_T = (0,0,1), z_T = (0,-1,0).
  c.R_T0 = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  c.t_T0 = {0, 60, 500};
  return c;
}

json intrinsics_to_json(const CameraIntrinsics& k) {
  return {{"K", k.K}, {"dist", k.dist}, {"width", k.width}, {"height", k.height}};
}

json turntable_cal_to_json(const TurntableCal& cal) { return {{"R_T0", cal.R_T0}, {"t_T0", cal.t_T0}}; }

}  // namespace fest::capture
