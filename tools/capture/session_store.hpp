#pragma once
// The files of a capture session (docs/capture.md §3, fest-capture(5)):
//   SESSION/a{ai:03}/{light}/e{k:02}.png ...  pictures, each written atomically
//   SESSION/manifest.journal                   one JSON line per shot, flushed + fsync'ed
//   SESSION/manifest.json                      rewritten atomically after every view
// A resumed session replays the journal and keeps the shots whose files still hash
// to their recorded SHA-256. Encoding, hashing and writing run on two encoder threads
// while the loop takes the next picture (at most four pictures in flight), as a rig's
// host overlaps saving with exposing. The journal still grows strictly in shot order,
// and a shot enters it only once its file is complete, flushed and renamed into place:
// encodes that finish early wait for their predecessors, and after a failure nothing
// later is journaled (its file, if written, is re-taken by --resume).

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "capture/manifest.hpp"
#include "capture/session.hpp"

namespace fest::capture_tool {

class SessionStore : public capture::ShotSink {
 public:
  // Creates SESSION (which must not hold a journal yet) and writes the journal header;
  // or, with resume, replays SESSION/manifest.journal (io_error when there is none;
  // bad_input when its plan differs from `plan`).
  SessionStore(const std::string& folder, bool resume, const nlohmann::json& plan, const std::string& format,
               int png_compression = 1);
  ~SessionStore() override;
  SessionStore(const SessionStore&) = delete;
  SessionStore& operator=(const SessionStore&) = delete;

  bool done(const capture::PlannedShot& shot) override;
  void store(const capture::PlannedShot& shot, const capture::ShotPose& pose, const Image& image) override;
  // Waits for the writer; rethrows its first error.
  void finish() override;
  // The same, errors dropped (an aborting session writes what it can).
  void finish_quietly();

  // Records an event line ({"abort": ...}) in the journal.
  void append(const nlohmann::json& entry);
  // manifest.json, atomically; returns its text.
  std::string write_manifest(capture::ManifestInfo info, const std::vector<capture::PlannedShot>& plan);

  const std::string& started() const { return started_; }
  const std::string& name() const { return name_; }
  int kept() const;
  double black_level = 0;
  std::vector<capture::PlannedShot> plan;  // for the per-view manifest rewrite
  capture::ManifestInfo info;

 private:
  std::string folder_, name_, started_, format_;
  int png_compression_ = 1;
  int journal_fd_ = -1;
  std::map<std::string, capture::ShotRecord> records_;
  std::set<std::string> verified_;
  int last_angle_ = -1;

  struct Job {
    std::uint64_t seq = 0;  // order of store() calls: the journal's order
    capture::PlannedShot shot;
    capture::ShotPose pose;
    Image image;
  };
  // A shot whose file is on disk (or whose encoding failed), waiting for its turn in the
  // journal.
  struct Written {
    capture::ShotRecord record;
    std::exception_ptr error;
    bool skipped = false;  // not encoded: an earlier shot had failed
  };
  capture::ShotRecord encode_and_write(const Job& job) const;
  void journal_shot(const capture::ShotRecord& record);
  void encoder_loop();
  void commit_in_order(std::unique_lock<std::mutex>& lock);
  void wait_idle(std::unique_lock<std::mutex>& lock);

  static constexpr int kEncoders = 2;
  static constexpr std::uint64_t kMaxInFlight = 4;  // pictures held in memory at most
  mutable std::mutex mutex_;  // guards everything below and records_/verified_
  std::condition_variable changed_;
  std::deque<Job> queue_;                  // stored, not yet taken by an encoder
  std::map<std::uint64_t, Written> written_;  // encoded, not yet journaled
  std::uint64_t next_seq_ = 0, commit_seq_ = 0;  // all before commit_seq_ are journaled or dropped
  bool committing_ = false, stopping_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> encoders_;
};

// ISO 8601 UTC with milliseconds.
std::string utc_now();

}  // namespace fest::capture_tool
