#pragma once
// Silences the console chatter of the codec libraries under OpenCV while they run.
// libpng ("libpng warning: iCCP: ..."), libtiff and OpenCV's own imdecode ("can't read
// header") write straight to file descriptor 2, and fest's libraries must not print
// (DESIGN.md); failures are reported by the empty result instead, which we turn into
// fest::Error. Descriptor 2 is process-wide, so the guard holds a mutex: codec calls
// under it are serialised, and another thread's stderr output in that short window is
// lost, an accepted cost since tools print diagnostics from the main thread after the
// work is done.

#include <mutex>

namespace fest::formats::image_detail {

class QuietStderr {
 public:
  QuietStderr();
  ~QuietStderr();
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  int saved_fd_ = -1;
};

}  // namespace fest::formats::image_detail
