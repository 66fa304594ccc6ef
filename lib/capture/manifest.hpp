#pragma once
// The session manifest (docs/capture.md §3, fest-capture(5)) and its journal, free of I/O.
//
// The journal (SESSION/manifest.journal) is the record that survives a crash: one JSON
// object per line, appended and flushed per shot --
//   {"journal":1,"session":...,"started":...,"plan":{...}}   first line
//   {"shot":{...manifest shot entry...}}                      one per stored picture
//   {"resume":"<time>"}  {"abort":{"step":...,"error":...}}   events
// manifest.json is derived from it: the planned shots in plan order, each with its latest
// journal record, and the (angle, light) exposure sets.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/plan.hpp"
#include "capture/session.hpp"

namespace fest::capture {

struct ShotRecord {
  PlannedShot shot;
  ShotPose pose;
  std::string time;    // ISO 8601 UTC
  std::string sha256;  // of the file's bytes, lower-case hex
  int bits = 16;
  double black_level = 0;
};

nlohmann::json shot_to_json(const ShotRecord& r);
// Throws bad_input naming where and the path.
ShotRecord shot_from_json(const nlohmann::json& j, const std::string& where, const std::string& path);

struct Journal {
  nlohmann::json header;
  std::map<std::string, ShotRecord> shots;  // by file, the latest record
  int records = 0;
  bool torn_tail = false;  // the last line was cut short by a crash and was ignored
};

// Replays a journal's text. A last line without its newline that does not parse is a
// write torn by a crash and is ignored; any other bad line is bad_input with its number.
Journal replay_journal(std::string_view text, const std::string& where);

nlohmann::json journal_header(const std::string& session, const std::string& started, const nlohmann::json& plan);
// One journal line, newline included.
std::string journal_line(const nlohmann::json& entry);

struct ManifestInfo {
  std::string session, started;
  std::string status = "complete";  // or "aborted"
  nlohmann::json station;           // the station document as given
  nlohmann::json camera;            // resolved: intrinsics_to_json + "name", "bits"
  nlohmann::json turntable;         // {"steps_per_rev", "cal": turntable_cal_to_json}
  nlohmann::json failure;           // for "aborted": {"step", "error", "exit_status"}
};

// shots: the planned shots present in `records`, in plan order; sets: per (angle, light)
// the indices of its hdr shots in that array, in exposure order.
nlohmann::json build_manifest(const ManifestInfo& info, const std::vector<PlannedShot>& plan,
                              const std::map<std::string, ShotRecord>& records);

}  // namespace fest::capture
