// Compute-only benchmark of resample's resize (docs/resample.md, R1/R2; target: compute only
// (no I/O), 1 thread, codes mode: ≤ 120 ms), in process on synthetic images, so the
// figures exclude file I/O and process start-up; tests/bench/resample_bench.sh measures
// end to end against the anchors. One JSON line per case, minimum of 3 runs, in ms.
//
//   build/bin/bench_resample
//   build/bin/bench_resample R1 codes 1   # that case only, once (for callgrind / time)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>

#include <sys/resource.h>

#include "core/image.hpp"
#include "sampling/resize.hpp"

// Under `valgrind --tool=callgrind --instr-atstart=no` the single-case mode switches
// instrumentation on around the resize only: building the input is not simulated.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

namespace {

using Clock = std::chrono::steady_clock;

// User + system CPU time of the process (all threads), in ms: on a loaded shared machine
// wall time mostly measures the neighbours.
double cpu_ms() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

struct Timing {
  double wall_ms, cpu_ms;  // each the minimum over the runs
};

Timing min_ms(int runs, const std::function<void()>& f) {
  Timing best{1e300, 1e300};
  for (int i = 0; i < runs; ++i) {
    const double cpu0 = cpu_ms();
    const auto start = Clock::now();
    f();
    best.wall_ms = std::min(best.wall_ms, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    best.cpu_ms = std::min(best.cpu_ms, cpu_ms() - cpu0);
  }
  return best;
}

// A photo-sized RGB8 image with detail at every scale (three zone plates).
fest::Image r1_input() {
  fest::Image img;
  img.pixels.create(3279, 4928, CV_8UC3);
  for (int y = 0; y < img.pixels.rows; ++y)
    for (int x = 0; x < img.pixels.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const double r2 = std::pow(x - 2464.0, 2) + std::pow(y - 1639.5, 2);
        img.pixels.ptr<std::uint8_t>(y)[3 * x + c] =
            static_cast<std::uint8_t>(127.5 + 127.5 * std::cos(3.14159265358979 * (0.03 + 0.01 * c) * r2 / 2464));
      }
  return img;
}

fest::Image r2_input() {
  fest::Image img;
  img.color_space = fest::ColorSpace::linear;
  img.pixels.create(8192, 8192, CV_32FC1);
  for (int y = 0; y < 8192; ++y)
    for (int x = 0; x < 8192; ++x) img.pixels.ptr<float>(y)[x] = static_cast<float>(0.5 + 0.5 * std::sin(0.001 * x * y));
  return img;
}

void report(const char* name, const char* mode, int threads, Timing t) {
  std::printf("{\"bench\":\"bench_resample\",\"case\":\"%s\",\"mode\":\"%s\",\"threads\":%d,\"ms\":%.1f,\"cpu_ms\":%.1f}\n", name,
              mode, threads, t.wall_ms, t.cpu_ms);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::sampling;
  if (argc == 4 && std::strcmp(argv[1], "R1") == 0) {  // one case, one run: for profilers
    const fest::Image in = r1_input();
    ResizeOptions o;
    o.kernel = make_kernel("lanczos3");
    o.linear_light = std::strcmp(argv[2], "linear") == 0;
    o.threads = std::atoi(argv[3]);
    report("R1", argv[2], o.threads, min_ms(1, [&] {
             CALLGRIND_START_INSTRUMENTATION;
             resize(in, 852, 567, o);
             CALLGRIND_STOP_INSTRUMENTATION;
           }));
    return 0;
  }
  {
    const fest::Image in = r1_input();
    for (int threads : {1, 2})
      for (bool linear : {false, true}) {
        ResizeOptions o;
        o.kernel = make_kernel("lanczos3");
        o.linear_light = linear;
        o.threads = threads;
        report("R1", linear ? "linear" : "codes", threads, min_ms(3, [&] { resize(in, 852, 567, o); }));
      }
  }
  {
    const fest::Image in = r2_input();
    ResizeOptions o;
    o.kernel = make_kernel("mitchell");
    o.threads = 2;
    report("R2", "float", 2, min_ms(3, [&] { resize(in, 1024, 1024, o); }));
  }
  return 0;
}
