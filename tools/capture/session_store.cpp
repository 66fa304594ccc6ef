#include "session_store.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>

#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/sha256.hpp"
#include "formats/image/image_io.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {

namespace fs = std::filesystem;
using nlohmann::json;

std::string utc_now() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  const long ms = long(std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return fmt::format("{}.{:03}Z", buf, ms);
}

namespace {

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw io_error("cannot append to {}: {}", path, std::strerror(errno));
    done += std::size_t(n);
  }
  if (::fsync(fd) != 0) throw io_error("cannot flush {}: {}", path, std::strerror(errno));
}

// A shot file as the journal may vouch for it: written under a temporary name, its data
// flushed to the disk, renamed into place and the rename flushed too. (Not AtomicFile:
// its commit sets permissions through umask(), which two encoder threads would race on;
// open()'s mode gets the umask applied without touching it.)
void write_durably(const std::string& path, const std::string& bytes) {
  const std::string temp = fmt::format("{}.tmp.{}", path, ::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw io_error("cannot create {}: {}", temp, std::strerror(errno));
  try {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw io_error("cannot write {}: {}", temp, std::strerror(errno));
      done += std::size_t(n);
    }
    if (::fdatasync(fd) != 0) throw io_error("cannot flush {}: {}", temp, std::strerror(errno));
  } catch (...) {
    ::close(fd);
    ::unlink(temp.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    ::unlink(temp.c_str());
    throw io_error("cannot write {}: {}", temp, std::strerror(errno));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    throw io_error("cannot rename {} into place: {}", path, std::strerror(saved));
  }
  const std::string folder = fs::path(path).parent_path().string();
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) throw io_error("cannot open {}: {}", folder, std::strerror(errno));
  const int synced = ::fsync(dir);
  ::close(dir);
  if (synced != 0) throw io_error("cannot flush {}: {}", folder, std::strerror(errno));
}

}  // namespace

SessionStore::SessionStore(const std::string& folder, bool resume, const json& plan_doc, const std::string& format,
                           int png_compression)
    : folder_(folder), format_(format), png_compression_(png_compression) {
  // The session is named by its folder as given, so that `capture run -o sess | hdrmerge
  // --manifest -` finds the files from the same working directory.
  name_ = folder;
  while (name_.size() > 1 && name_.back() == '/') name_.pop_back();
  const std::string journal = (fs::path(folder) / "manifest.journal").string();
  std::error_code ec;
  if (resume) {
    if (!fs::is_directory(folder, ec)) throw io_error("cannot resume: no session folder {}", folder);
    if (!fs::exists(journal, ec)) throw io_error("cannot resume: no journal {}", journal);
    const std::string text = read_input(journal);
    const capture::Journal j = capture::replay_journal(text, journal);
    // A line torn by a crash is cut off, so that the lines appended now start clean.
    if (j.torn_tail) {
      fs::resize_file(journal, text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1, ec);
      if (ec) throw io_error("cannot cut the torn last line of {}: {}", journal, ec.message());
    }
    if (j.header.value("plan", json()) != plan_doc)
      throw bad_input("the plan differs from the one the session was started with ({})", journal);
    if (j.header.contains("started") && !j.header["started"].is_string())
      throw bad_input("the session journal's \"started\" is not a time stamp ({})", journal);
    started_ = j.header.value("started", "");
    for (const auto& [file, record] : j.shots) {
      const fs::path p = fs::path(folder) / file;
      if (!fs::is_regular_file(p, ec)) continue;
      if (sha256_hex(read_input(p.string())) != record.sha256) continue;
      records_[file] = record;
      verified_.insert(file);
    }
  } else {
    if (fs::exists(journal, ec)) throw io_error("{} already holds a session (use --resume to continue it)", folder);
    fs::create_directories(folder, ec);
    if (ec) throw io_error("cannot create {}: {}", folder, ec.message());
    started_ = utc_now();
  }
  journal_fd_ = ::open(journal.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (journal_fd_ < 0) throw io_error("cannot open {}: {}", journal, std::strerror(errno));
  if (resume) append({{"resume", utc_now()}});
  else append(capture::journal_header(name_, started_, plan_doc));
}

SessionStore::~SessionStore() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : encoders_) t.join();
  if (journal_fd_ >= 0) ::close(journal_fd_);
}

void SessionStore::encoder_loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, and every stored shot taken
    Job job = std::move(queue_.front());
    queue_.pop_front();
    Written w;
    w.skipped = bool(error_);  // a failed session writes no more files
    lock.unlock();
    if (!w.skipped) {
      try {
        w.record = encode_and_write(job);
      } catch (...) {
        w.error = std::current_exception();
      }
    }
    job.image = Image{};  // the picture's memory goes before waiting for the lock
    lock.lock();
    written_.emplace(job.seq, std::move(w));
    commit_in_order(lock);
  }
}

// Journals the written shots that are next in line. One thread commits at a time (the
// others leave their shots in written_ for it), so the lines follow shot order; the lock
// is released around the fsync'ed append.
void SessionStore::commit_in_order(std::unique_lock<std::mutex>& lock) {
  if (committing_) return;
  committing_ = true;
  for (auto it = written_.find(commit_seq_); it != written_.end(); it = written_.find(commit_seq_)) {
    Written w = std::move(it->second);
    written_.erase(it);
    if (w.error && !error_) error_ = w.error;
    if (!error_ && !w.skipped) {
      lock.unlock();
      std::exception_ptr e;
      try {
        journal_shot(w.record);
      } catch (...) {
        e = std::current_exception();
      }
      lock.lock();
      if (e && !error_) error_ = e;
      if (!e) {
        records_[w.record.shot.file] = w.record;
        verified_.insert(w.record.shot.file);
      }
    }
    ++commit_seq_;
    changed_.notify_all();
  }
  committing_ = false;
  changed_.notify_all();
}

void SessionStore::wait_idle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [&] { return commit_seq_ == next_seq_ && !committing_; });
}

void SessionStore::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  wait_idle(lock);
  if (error_) std::rethrow_exception(error_);
}

void SessionStore::finish_quietly() {
  std::unique_lock<std::mutex> lock(mutex_);
  wait_idle(lock);
}

void SessionStore::append(const json& entry) {
  write_all(journal_fd_, capture::journal_line(entry), folder_ + "/manifest.journal");
}

bool SessionStore::done(const capture::PlannedShot& shot) {
  std::lock_guard<std::mutex> lock(mutex_);
  return verified_.count(shot.file) > 0;
}

int SessionStore::kept() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(verified_.size());
}

void SessionStore::store(const capture::PlannedShot& shot, const capture::ShotPose& pose, const Image& image) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return next_seq_ - commit_seq_ < kMaxInFlight || error_; });
  if (error_) std::rethrow_exception(error_);
  if (encoders_.empty())
    for (int i = 0; i < kEncoders; ++i) encoders_.emplace_back([this] { encoder_loop(); });
  queue_.push_back({next_seq_++, shot, pose, image});
  changed_.notify_all();
}

// On an encoder thread: the picture's bytes, durably in place under their name.
capture::ShotRecord SessionStore::encode_and_write(const Job& job) const {
  const capture::PlannedShot& shot = job.shot;
  cv::Mat pixels = job.image.pixels;
  if (format_ == "png8" && pixels.depth() == CV_16U) pixels.convertTo(pixels, CV_8U, 1.0 / 257.0);
  const formats::Format f = format_ == "tiff16" ? formats::Format::tiff : formats::Format::png;
  // Huffman coding only: the shots are noisy raw data, where string matching finds
  // little; at level 1 on the simulated station's shots it is 1.6x faster than the default
  // strategy and 15 % smaller (level 6: 3x slower). Level 0 stores: 2x faster again,
  // 2.3x the size.
  formats::ImageWriteOptions w;
  w.png_compression = png_compression_;
  w.png_huffman_only = png_compression_ > 0;
  const std::string bytes = formats::write_image(Image{pixels, job.image.color_space}, f, w);
  const fs::path path = fs::path(folder_) / shot.file;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) throw io_error("cannot create {}: {}", path.parent_path().string(), ec.message());
  write_durably(path.string(), bytes);
  capture::ShotRecord r;
  r.shot = shot;
  r.pose = job.pose;
  r.time = utc_now();
  r.sha256 = sha256_hex(bytes);
  r.bits = pixels.depth() == CV_16U ? 16 : 8;
  r.black_level = black_level;
  return r;
}

// On the committing thread, in shot order.
void SessionStore::journal_shot(const capture::ShotRecord& record) {
  // A new view: the manifest of everything so far is written first (cheap, per view).
  if (record.shot.angle_index != last_angle_ && last_angle_ >= 0 && !plan.empty()) {
    capture::ManifestInfo partial = info;
    partial.status = "running";
    write_manifest(partial, plan);
  }
  last_angle_ = record.shot.angle_index;
  append({{"shot", capture::shot_to_json(record)}});
}

std::string SessionStore::write_manifest(capture::ManifestInfo i, const std::vector<capture::PlannedShot>& shots) {
  i.session = name_;
  i.started = started_;
  std::map<std::string, capture::ShotRecord> records;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    records = records_;
  }
  const std::string text = formats::write_json(capture::build_manifest(i, shots, records));
  write_output((fs::path(folder_) / "manifest.json").string(), text);
  return text;
}

}  // namespace fest::capture_tool
