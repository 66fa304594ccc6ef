#pragma once
// The files of a capture session (specs/capture.md §2.5, §4):
//   SESSION/a{ai:03}/{light}/e{k:02}.png ...  pictures, each written atomically
//   SESSION/manifest.journal                   one JSON line per shot, flushed + fsync'ed
//   SESSION/manifest.json                      rewritten atomically after every view
// A resumed session replays the journal and keeps the shots whose files still hash
// to their recorded SHA-256.

#include <map>
#include <set>
#include <string>

#include "capture/manifest.hpp"
#include "capture/session.hpp"

namespace fest::capture_tool {

class SessionStore : public capture::ShotSink {
 public:
  // Creates SESSION (which must not hold a journal yet) and writes the journal header;
  // or, with resume, replays SESSION/manifest.journal (io_error when there is none;
  // bad_input when its plan differs from `plan`).
  SessionStore(const std::string& folder, bool resume, const nlohmann::json& plan, const std::string& format);
  ~SessionStore() override;
  SessionStore(const SessionStore&) = delete;
  SessionStore& operator=(const SessionStore&) = delete;

  bool done(const capture::PlannedShot& shot) override;
  void store(const capture::PlannedShot& shot, const capture::ShotPose& pose, const Image& image) override;

  // Records an event line ({"abort": ...}) in the journal.
  void append(const nlohmann::json& entry);
  // manifest.json, atomically; returns its text.
  std::string write_manifest(capture::ManifestInfo info, const std::vector<capture::PlannedShot>& plan);

  const std::string& started() const { return started_; }
  const std::string& name() const { return name_; }
  int kept() const { return int(verified_.size()); }
  double black_level = 0;
  std::vector<capture::PlannedShot> plan;  // for the per-view manifest rewrite
  capture::ManifestInfo info;

 private:
  std::string folder_, name_, started_, format_;
  int journal_fd_ = -1;
  std::map<std::string, capture::ShotRecord> records_;
  std::set<std::string> verified_;
  int last_angle_ = -1;
};

// ISO 8601 UTC with milliseconds.
std::string utc_now();

}  // namespace fest::capture_tool
