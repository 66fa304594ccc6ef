#include "capture/manifest.hpp"

#include "capture/json_fields.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::capture {

using nlohmann::json;

json shot_to_json(const ShotRecord& r) {
  const PlannedShot& s = r.shot;
  json j;
  j["file"] = s.file;
  j["kind"] = shot_kind_name(s.kind);
  j["angle_index"] = s.angle_index;
  j["angle_cmd_deg"] = s.angle_cmd_deg;
  j["angle_deg"] = r.pose.angle_deg;
  j["angle_steps"] = r.pose.angle_steps;
  if (!s.light.empty()) j["light"] = s.light;
  j["lights_on"] = s.lights_on;
  j["exposure_index"] = s.exposure_index;
  j["exposure_s"] = s.exposure_s;
  if (s.repeat_index > 0) j["repeat_index"] = s.repeat_index;  // only plans with "repeat" > 1 have takes
  j["time"] = r.time;
  j["sha256"] = r.sha256;
  j["black_level"] = r.black_level;
  j["bits"] = r.bits;
  return j;
}

ShotRecord shot_from_json(const json& j, const std::string& where, const std::string& path) {
  const JsonFields f(where);
  f.keys(j, path, {"file", "kind", "angle_index", "angle_cmd_deg", "angle_deg", "angle_steps", "light", "lights_on",
                   "exposure_index", "exposure_s", "repeat_index", "time", "sha256", "black_level", "bits"});
  for (const char* k : {"file", "kind", "angle_index", "angle_cmd_deg", "angle_deg", "angle_steps", "exposure_s", "sha256"})
    if (!j.contains(k)) f.fail("missing", json_path(path, k));
  ShotRecord r;
  PlannedShot& s = r.shot;
  s.file = f.string(j["file"], json_path(path, "file"));
  if (s.file.front() == '/' || s.file.find("..") != std::string::npos)
    f.fail("must be a path inside the session", json_path(path, "file"));
  const std::string kind = f.string(j["kind"], json_path(path, "kind"));
  if (kind == "hdr") s.kind = ShotKind::hdr;
  else if (kind == "silhouette") s.kind = ShotKind::silhouette;
  else if (kind == "lightcal") s.kind = ShotKind::lightcal;
  else if (kind == "dark") s.kind = ShotKind::dark;
  else f.fail("must be hdr, silhouette, lightcal or dark", json_path(path, "kind"));
  s.angle_index = f.integer(j["angle_index"], json_path(path, "angle_index"), 0, 1 << 20);
  s.angle_cmd_deg = f.number(j["angle_cmd_deg"], json_path(path, "angle_cmd_deg"), -1e6, 1e6);
  r.pose.angle_deg = f.number(j["angle_deg"], json_path(path, "angle_deg"), -1e6, 1e6);
  r.pose.angle_steps = f.integer(j["angle_steps"], json_path(path, "angle_steps"), -2147483647, 2147483647);
  if (j.contains("light")) s.light = f.string(j["light"], json_path(path, "light"));
  if (s.kind == ShotKind::hdr && s.light.empty()) f.fail("an hdr shot needs its light", json_path(path, "light"));
  if (j.contains("lights_on")) s.lights_on = f.strings(j["lights_on"], json_path(path, "lights_on"));
  if (j.contains("exposure_index")) s.exposure_index = f.integer(j["exposure_index"], json_path(path, "exposure_index"), 0, 1000);
  s.exposure_s = f.positive(j["exposure_s"], json_path(path, "exposure_s"));
  if (j.contains("repeat_index")) s.repeat_index = f.integer(j["repeat_index"], json_path(path, "repeat_index"), 0, 99);
  if (j.contains("time") && j["time"].is_string()) r.time = j["time"].get<std::string>();
  r.sha256 = f.string(j["sha256"], json_path(path, "sha256"));
  if (r.sha256.size() != 64 || r.sha256.find_first_not_of("0123456789abcdef") != std::string::npos)
    f.fail("must be 64 lower-case hex digits", json_path(path, "sha256"));
  if (j.contains("black_level")) r.black_level = f.number(j["black_level"], json_path(path, "black_level"), 0, 65535);
  if (j.contains("bits")) {
    r.bits = f.integer(j["bits"], json_path(path, "bits"), 8, 16);
    if (r.bits != 8 && r.bits != 16) f.fail("must be 8 or 16", json_path(path, "bits"));
  }
  return r;
}

Journal replay_journal(std::string_view text, const std::string& where) {
  Journal journal;
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const bool last_unterminated = nl == std::string_view::npos;
    const std::string_view line = text.substr(pos, last_unterminated ? std::string_view::npos : nl - pos);
    pos = last_unterminated ? text.size() : nl + 1;
    ++line_no;
    const std::string here = fmt::format("{} line {}", where, line_no);
    json entry;
    try {
      entry = json::parse(line);
    } catch (const json::exception&) {
      if (last_unterminated) {
        journal.torn_tail = true;
        break;
      }
      throw bad_input("not a JSON line ({})", here);
    }
    if (line_no == 1) {
      if (!entry.is_object() || !entry.contains("journal") || entry["journal"] != 1)
        throw bad_input("not a capture journal: the first line lacks \"journal\": 1 ({})", here);
      journal.header = entry;
      continue;
    }
    if (!entry.is_object() || entry.size() != 1) throw bad_input("a journal entry is one object with one key ({})", here);
    if (entry.contains("shot")) {
      ShotRecord r = shot_from_json(entry["shot"], here, "shot");
      const std::string file = r.shot.file;
      journal.shots[file] = std::move(r);
      ++journal.records;
    } else if (!entry.contains("resume") && !entry.contains("abort")) {
      throw bad_input("unknown journal entry \"{}\" ({})", quoted_bytes(entry.begin().key()), here);
    }
  }
  if (line_no == 0) throw bad_input("empty journal ({})", where);
  return journal;
}

json journal_header(const std::string& session, const std::string& started, const json& plan) {
  return {{"journal", 1}, {"session", session}, {"started", started}, {"plan", plan}};
}

std::string journal_line(const json& entry) { return entry.dump() + "\n"; }

json build_manifest(const ManifestInfo& info, const std::vector<PlannedShot>& plan,
                    const std::map<std::string, ShotRecord>& records) {
  json m;
  m["version"] = 1;
  m["status"] = info.status;
  m["session"] = info.session;
  m["started"] = info.started;
  m["station"] = info.station;
  m["camera"] = info.camera;
  m["turntable"] = info.turntable;
  if (!info.failure.is_null()) m["failure"] = info.failure;
  json shots = json::array();
  json sets = json::array();
  int set_angle = -1;
  std::string set_light;
  for (const PlannedShot& s : plan) {
    auto it = records.find(s.file);
    if (it == records.end()) continue;
    const int index = int(shots.size());
    shots.push_back(shot_to_json(it->second));
    if (s.kind != ShotKind::hdr) continue;
    if (sets.empty() || s.angle_index != set_angle || s.light != set_light) {
      sets.push_back({{"angle_index", s.angle_index}, {"light", s.light}, {"shots", json::array()}});
      set_angle = s.angle_index;
      set_light = s.light;
    }
    sets.back()["shots"].push_back(index);
  }
  m["shots"] = shots;
  m["sets"] = sets;
  return m;
}

}  // namespace fest::capture
