#include "capture/plan.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "capture/json_fields.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::capture {

using nlohmann::json;

std::vector<double> even_angles(int count) {
  std::vector<double> a;
  for (int i = 0; i < count; ++i) a.push_back(360.0 * i / count);
  return a;
}

std::vector<double> bracket_exposures(double base_s, double stops, int count) {
  std::vector<double> t;
  for (int k = 0; k < count; ++k) t.push_back(base_s * std::pow(2.0, stops * k));
  return t;
}

namespace {

double parse_number(const std::string& text, const char* what) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v))
    throw usage_error("{} '{}' is not a number", what, text);
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t p = text.find(sep, start);
    parts.push_back(text.substr(start, p == std::string::npos ? std::string::npos : p - start));
    if (p == std::string::npos) return parts;
    start = p + 1;
  }
}

void check_increasing(const JsonFields& f, const std::vector<double>& t, const std::string& path) {
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!(t[k] > 0) || t[k] > 3600) f.fail("exposure times must be in (0, 3600] s", path);
    if (k > 0 && !(t[k] > t[k - 1])) f.fail("exposure times must increase strictly", path);
  }
}

}  // namespace

double seconds_from_text(const std::string& text) {
  const std::size_t slash = text.find('/');
  double v = 0;
  if (slash == std::string::npos) v = parse_number(text, "exposure time");
  else v = parse_number(text.substr(0, slash), "exposure time") / parse_number(text.substr(slash + 1), "exposure time");
  if (!(v > 0) || !std::isfinite(v)) throw usage_error("exposure time '{}' must be positive", text);
  return v;
}

std::vector<double> angles_from_flag(const std::string& text) {
  if (text.find(',') == std::string::npos) {
    const double n = parse_number(text, "turntable angle count");
    if (n < 1 || n > 100000 || n != std::floor(n))
      throw usage_error("turntable angle count {} must be a whole number in 1..100000", text);
    return even_angles(int(n));
  }
  std::vector<double> a;
  for (const std::string& p : split(text, ',')) a.push_back(parse_number(p, "turntable angle"));
  return a;
}

std::vector<double> exposures_from_flag(const std::string& text) {
  std::vector<double> t;
  if (text.find(':') != std::string::npos) {
    const std::vector<std::string> p = split(text, ':');
    if (p.size() != 3) throw usage_error("exposure bracket '{}': expected BASE:STOPS:COUNT, e.g. 1/1000:1:12", text);
    const double base = seconds_from_text(p[0]);
    const double stops = parse_number(p[1], "bracket stops");
    const double count = parse_number(p[2], "bracket count");
    if (!(stops > 0) || stops > 8) throw usage_error("bracket stops must be in (0, 8], not {}", p[1]);
    if (count < 1 || count > 64 || count != std::floor(count))
      throw usage_error("bracket count must be a whole number in 1..64, not {}", p[2]);
    t = bracket_exposures(base, stops, int(count));
  } else {
    for (const std::string& p : split(text, ',')) t.push_back(seconds_from_text(p));
  }
  for (std::size_t k = 1; k < t.size(); ++k)
    if (!(t[k] > t[k - 1])) throw usage_error("the bracket's exposure times must increase");
  return t;
}

Plan parse_plan(const json& doc, const std::string& where) {
  const JsonFields f(where);
  f.keys(doc, "", {"angles_deg", "lights", "exposures_s", "auto_bracket", "per_view", "repeat"});
  Plan p;
  if (!doc.contains("angles_deg")) f.fail("missing", "angles_deg");
  if (!doc.contains("lights")) f.fail("missing", "lights");
  if (!doc.contains("exposures_s")) f.fail("missing", "exposures_s");

  const json& a = doc["angles_deg"];
  if (a.is_object()) {
    f.keys(a, "angles_deg", {"count"});
    if (!a.contains("count")) f.fail("missing", "angles_deg.count");
    p.angles_deg = even_angles(f.integer(a["count"], "angles_deg.count", 1, 100000));
  } else {
    p.angles_deg = f.numbers(a, "angles_deg", 0);
    for (double x : p.angles_deg)
      if (std::fabs(x) > 36000) f.fail("angles must be within +-36000 deg", "angles_deg");
  }

  const json& l = doc["lights"];
  if (l.is_string() && l.get<std::string>() == "each") p.each_light = true;
  else {
    if (!l.is_array()) f.fail("must be \"each\" or an array of light ids", "lights");
    p.lights = f.strings(l, "lights");
    if (p.lights.empty()) f.fail("must name at least one light", "lights");
  }

  const json& e = doc["exposures_s"];
  if (e.is_object()) {
    f.keys(e, "exposures_s", {"base", "stops", "count"});
    for (const char* k : {"base", "stops", "count"})
      if (!e.contains(k)) f.fail("missing", std::string("exposures_s.") + k);
    p.exposures_s = bracket_exposures(f.positive(e["base"], "exposures_s.base"),
                                      f.number(e["stops"], "exposures_s.stops", 0.01, 8),
                                      f.integer(e["count"], "exposures_s.count", 1, 64));
  } else {
    p.exposures_s = f.numbers(e, "exposures_s", 0);
  }
  check_increasing(f, p.exposures_s, "exposures_s");

  if (doc.contains("auto_bracket") && f.boolean(doc["auto_bracket"], "auto_bracket"))
    f.fail("true is not supported by this version (give exposures_s explicitly)", "auto_bracket");
  if (doc.contains("repeat")) p.repeat = f.integer(doc["repeat"], "repeat", 1, 100);

  if (doc.contains("per_view")) {
    const json& v = doc["per_view"];
    f.keys(v, "per_view", {"silhouette", "lightcal", "dark"});
    if (v.contains("silhouette")) {
      const json& s = v["silhouette"];
      f.keys(s, "per_view.silhouette", {"lights_on", "exposure_s"});
      p.silhouette = true;
      if (s.contains("lights_on")) p.silhouette_lights = f.strings(s["lights_on"], "per_view.silhouette.lights_on");
      if (s.contains("exposure_s")) p.silhouette_exposure_s = f.positive(s["exposure_s"], "per_view.silhouette.exposure_s");
    }
    for (const char* name : {"lightcal", "dark"}) {
      if (!v.contains(name)) continue;
      const std::string path = std::string("per_view.") + name;
      f.keys(v[name], path, {"count", "exposure_s"});
      ViewShots& shots = std::string(name) == "dark" ? p.dark : p.lightcal;
      if (v[name].contains("count")) shots.count = f.integer(v[name]["count"], path + ".count", 0, 100);
      if (v[name].contains("exposure_s")) shots.exposure_s = f.positive(v[name]["exposure_s"], path + ".exposure_s");
    }
  }
  return p;
}

json plan_to_json(const Plan& p) {
  json doc;
  doc["angles_deg"] = p.angles_deg;
  if (p.each_light) doc["lights"] = "each";
  else doc["lights"] = p.lights;
  doc["exposures_s"] = p.exposures_s;
  doc["auto_bracket"] = false;
  json view = json::object();
  if (p.silhouette) view["silhouette"] = {{"lights_on", p.silhouette_lights}, {"exposure_s", p.silhouette_exposure_s}};
  auto shots = [](const ViewShots& s) {
    json j = {{"count", s.count}};
    if (s.exposure_s > 0) j["exposure_s"] = s.exposure_s;
    return j;
  };
  if (p.lightcal.count > 0) view["lightcal"] = shots(p.lightcal);
  if (p.dark.count > 0) view["dark"] = shots(p.dark);
  doc["per_view"] = view;
  doc["repeat"] = p.repeat;
  return doc;
}

const char* shot_kind_name(ShotKind k) {
  switch (k) {
    case ShotKind::hdr: return "hdr";
    case ShotKind::silhouette: return "silhouette";
    case ShotKind::lightcal: return "lightcal";
    case ShotKind::dark: return "dark";
  }
  return "hdr";
}

std::vector<std::string> plan_lights(const Plan& plan, const Station& station) {
  if (!plan.each_light) return plan.lights;
  std::vector<std::string> ids;
  for (const LightConfig& l : station.lights)
    if (l.role == "light") ids.push_back(l.id);
  return ids;
}

std::vector<PlannedShot> expand_plan(const Plan& plan, const Station& station, const std::string& extension,
                                     const std::string& where) {
  const JsonFields f(where);
  const std::vector<std::string> lights = plan_lights(plan, station);
  if (lights.empty()) f.fail("the station has no light with role \"light\"", "lights");
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const LightConfig* l = station.light(lights[i]);
    if (!l) f.fail(fmt::format("light \"{}\" is not in the station", quoted_bytes(lights[i])), fmt::format("lights[{}]", i));
    for (std::size_t j = 0; j < i; ++j)
      if (lights[j] == lights[i]) f.fail(fmt::format("names light \"{}\" twice", quoted_bytes(lights[i])), fmt::format("lights[{}]", i));
    // The thermal limit: a light stays on for its warm-up and its whole series.
    double on_s = l->warmup_ms / 1000.0;
    for (double t : plan.exposures_s) on_s += t * plan.repeat;
    if (l->max_on_s > 0 && on_s > l->max_on_s)
      f.fail(fmt::format("light \"{}\" would stay on {:.3g} s per series, over its max_on_s {} s", quoted_bytes(l->id), on_s, l->max_on_s),
             fmt::format("lights[{}]", i));
  }
  for (std::size_t i = 0; i < plan.silhouette_lights.size(); ++i)
    if (!station.light(plan.silhouette_lights[i]))
      f.fail(fmt::format("light \"{}\" is not in the station", quoted_bytes(plan.silhouette_lights[i])),
             fmt::format("per_view.silhouette.lights_on[{}]", i));
  const double shortest = plan.exposures_s.front();

  std::vector<PlannedShot> shots;
  for (std::size_t ai = 0; ai < plan.angles_deg.size(); ++ai) {
    PlannedShot base;
    base.angle_index = int(ai);
    base.angle_cmd_deg = plan.angles_deg[ai];
    const std::string folder = fmt::format("a{:03}/", ai);
    if (plan.silhouette) {
      PlannedShot s = base;
      s.kind = ShotKind::silhouette;
      s.lights_on = plan.silhouette_lights;
      s.exposure_s = plan.silhouette_exposure_s;
      s.file = folder + "sil" + extension;
      shots.push_back(s);
    }
    for (int k = 0; k < plan.lightcal.count; ++k) {
      PlannedShot s = base;
      s.kind = ShotKind::lightcal;
      s.light = lights[std::size_t(k) % lights.size()];
      s.lights_on = {s.light};
      s.exposure_index = k;
      s.exposure_s = plan.lightcal.exposure_s > 0 ? plan.lightcal.exposure_s : shortest;
      s.file = fmt::format("{}lightcal_{}{}", folder, k, extension);
      shots.push_back(s);
    }
    for (int k = 0; k < plan.dark.count; ++k) {
      PlannedShot s = base;
      s.kind = ShotKind::dark;
      s.exposure_index = k;
      s.exposure_s = plan.dark.exposure_s > 0 ? plan.dark.exposure_s : shortest;
      s.file = fmt::format("{}dark_{}{}", folder, k, extension);
      shots.push_back(s);
    }
    for (const std::string& l : lights)
      for (std::size_t k = 0; k < plan.exposures_s.size(); ++k)
        for (int r = 0; r < plan.repeat; ++r) {  // the takes of one exposure back to back
          PlannedShot s = base;
          s.kind = ShotKind::hdr;
          s.light = l;
          s.lights_on = {l};
          s.exposure_index = int(k);
          s.repeat_index = r;
          s.exposure_s = plan.exposures_s[k];
          s.file = plan.repeat == 1 ? fmt::format("{}{}/e{:02}{}", folder, l, k, extension)
                                    : fmt::format("{}{}/e{:02}_r{}{}", folder, l, k, r, extension);
          shots.push_back(s);
        }
  }
  return shots;
}

}  // namespace fest::capture
