#include "devices/exec_camera.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"

extern char** environ;

namespace fest::devices {

namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string shutter_text(double t) {
  if (t >= 1) return fmt::format("{:g}", t);
  return fmt::format("1/{}", std::lround(1 / t));
}

}  // namespace

ExecCamera::ExecCamera(std::string command, double timeout_s) : command_(std::move(command)), timeout_s_(timeout_s) {
  if (command_.empty()) throw usage_error("exec camera: empty command template");
  if (command_.find("{out}") == std::string::npos)
    throw usage_error("exec camera: the command template has no {{out}} placeholder");
  info_.name = "exec: " + command_;
}

capture::CameraInfo ExecCamera::info() { return info_; }

void ExecCamera::set_exposure(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) throw usage_error("exec camera: exposure {} s must be positive", seconds);
  exposure_s_ = seconds;
}

std::string ExecCamera::expand(const std::string& out_path) const {
  std::string c = command_;
  replace_all(c, "{out}", shell_quote(out_path));
  replace_all(c, "{exposure_s}", fmt::format("{:g}", exposure_s_));
  replace_all(c, "{shutter}", shutter_text(exposure_s_));
  replace_all(c, "{iso}", "");
  replace_all(c, "{index}", std::to_string(index_));
  return c;
}

Image ExecCamera::capture() {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / fmt::format("fest-exec-camera-{}-{}", ::getpid(), index_);
  const std::string command = expand(out.string());
  std::error_code ec;
  fs::remove(out, ec);
  pid_t pid = 0;
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    throw make_error(Status::device_error, "exec camera: cannot start /bin/sh");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s_);
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      fs::remove(out, ec);
      throw make_error(Status::timeout, "exec camera: the command did not deliver within {} s ({})", timeout_s_, command_);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ++index_;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fs::remove(out, ec);
    throw make_error(Status::device_error, "exec camera: the command failed (exit {}) ({})",
                     WIFEXITED(status) ? WEXITSTATUS(status) : -1, command_);
  }
  if (!fs::exists(out, ec))
    throw make_error(Status::timeout, "exec camera: the command wrote no picture to {{out}} ({})", command_);
  const std::string bytes = read_input(out.string());
  fs::remove(out, ec);
  Image image;
  try {
    image = formats::read_image(bytes, formats::detect_format(bytes, out.string()));
  } catch (const Error& e) {
    throw make_error(Status::device_error, "exec camera: unreadable picture: {}", e.what());
  }
  if (image.pixels.depth() == CV_32F) throw make_error(Status::device_error, "exec camera: the picture is not 8 or 16-bit");
  info_.width = image.pixels.cols;
  info_.height = image.pixels.rows;
  info_.channels = image.pixels.channels();
  info_.bits = image.pixels.depth() == CV_16U ? 16 : 8;
  return image;
}

}  // namespace fest::devices
