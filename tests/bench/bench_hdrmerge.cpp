// hdrmerge against OpenCV's photo module (docs/hdrmerge.md §6): the same synthetic
// series -- 3040x2008 RGB by default, 12 exposures 1 ms .. 2.048 s, gamma-2.2 camera with
// 0.5 DN of read noise, radiance over 4 decades -- through lib/hdr's Debevec-Malik
// calibration and merge, and through cv::CalibrateDebevec(70, 10) + cv::MergeDebevec.
// Each engine runs in its own forked child so its peak memory (ru_maxrss, including the
// 8-bit inputs it generates) is its own. One JSON line per engine.
//
//   bench_hdrmerge [--width 3040] [--height 2008] [--exposures 12] [--threads 0]

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/photo.hpp>

#include "core/threads.hpp"
#include "hdr/debevec.hpp"
#include "hdr/merge.hpp"

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Setup {
  int width = 3040, height = 2008, exposures = 12, threads = 0;
};

// The analytic radiance, recomputed where needed so no float copy is held.
double radiance(const Setup& s, int x, int y, int c) {
  const double u = std::fmin(1.0, std::fmax(0.0, (x + 0.5) / s.width + 0.05 * std::sin(6.283185307179586 * y / s.height)));
  return std::pow(10.0, -2.0 + 4.0 * u) * (1.0 - 0.2 * c);
}

std::vector<double> times_of(const Setup& s) {
  std::vector<double> t;
  for (int k = 0; k < s.exposures; ++k) t.push_back(0.001 * std::pow(2.0, k));
  return t;
}

// Gamma-2.2 camera, 0.5 DN Gaussian noise, 8-bit rounding; a lookup of E^(1/2.2) per
// pixel and channel keeps generation cheap.
std::vector<cv::Mat> bracket(const Setup& s) {
  const std::vector<double> times = times_of(s);
  std::vector<cv::Mat> images;
  for (int k = 0; k < s.exposures; ++k) images.emplace_back(s.height, s.width, CV_8UC3);
  cv::RNG rng(12345);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double e = radiance(s, x, y, c);
        for (int k = 0; k < s.exposures; ++k) {
          const double v = 255.0 * std::pow(std::fmin(1.0, e * times[std::size_t(k)]), 1 / 2.2) + rng.gaussian(0.5);
          images[std::size_t(k)].ptr<std::uint8_t>(y)[x * 3 + c] = std::uint8_t(std::lround(std::fmin(255.0, std::fmax(0.0, v))));
        }
      }
  return images;
}

// RMS of ln(merged / E) minus its mean over pixels with a finite positive value.
double log_rms(const Setup& s, const cv::Mat& merged) {
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double m = merged.ptr<float>(y)[x * 3 + c];
        if (!(m > 0 && std::isfinite(m))) continue;
        const double d = std::log(m / radiance(s, x, y, c));
        sum += d;
        sum2 += d * d;
        ++n;
      }
  const double mean = sum / double(n);
  return std::sqrt(std::fmax(0.0, sum2 / double(n) - mean * mean));
}

// Worst |exp(g(z) - g(128) - 2.2 ln(z/128)) - 1| over z 10..245 and channels.
template <typename LogInverse>
double response_error(LogInverse&& g) {
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int z = 10; z <= 245; ++z)
      worst = std::fmax(worst, std::fabs(std::expm1(g(c, z) - g(c, 128) - 2.2 * std::log(z / 128.0))));
  return worst;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// CPU seconds of the whole process (all threads): on a shared, loaded machine the wall
// time says little, the CPU time still compares the engines' work.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double peak_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

json base(const Setup& s, const char* engine) {
  return {{"bench", "hdrmerge"}, {"engine", engine}, {"width", s.width}, {"height", s.height},
          {"exposures", s.exposures}, {"camera", "gamma 2.2, sigma 0.5 DN"}};
}

void run_fest(const Setup& s) {
  const std::vector<cv::Mat> images = bracket(s);
  fest::hdr::ExposureStack stack{images, times_of(s)};
  const int threads = fest::resolve_threads(s.threads);
  json j = base(s, "fest lib/hdr");
  j["threads"] = threads;
  for (int samples : {70, fest::hdr::DebevecOptions{}.samples}) {
    fest::hdr::DebevecOptions o;
    o.samples = samples;
    const auto t0 = Clock::now();
    const fest::hdr::Response r = fest::hdr::recover_response_debevec(stack, o);
    j["calibrate_s_N" + std::to_string(samples)] = seconds_since(t0);
    j["response_err_N" + std::to_string(samples)] =
        response_error([&](int c, int z) { return r.g[std::size_t(c)][std::size_t(z)]; });
  }
  const fest::hdr::Response r = fest::hdr::recover_response_debevec(stack);
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  const fest::hdr::MergeResult m = fest::hdr::merge_debevec(stack, r, threads);
  j["merge_s"] = seconds_since(t0);
  j["merge_cpu_s"] = cpu_seconds() - c0;
  j["peak_mb"] = peak_mb();
  j["log_rms"] = log_rms(s, m.radiance);
  std::printf("%s\n", j.dump().c_str());
}

void run_opencv(const Setup& s) {
  const std::vector<cv::Mat> images = bracket(s);
  std::vector<float> times;
  for (double t : times_of(s)) times.push_back(float(t));
  json j = base(s, "OpenCV " CV_VERSION " photo");
  j["threads"] = cv::getNumThreads();
  cv::Mat response;
  auto t0 = Clock::now();
  cv::createCalibrateDebevec(70, 10.f, false)->process(images, response, times);
  j["calibrate_s_N70"] = seconds_since(t0);
  j["response_err_N70"] = response_error([&](int c, int z) { return std::log(double(response.at<cv::Vec3f>(z)[c])); });
  cv::Mat hdr;
  t0 = Clock::now();
  const double c0 = cpu_seconds();
  cv::createMergeDebevec()->process(images, hdr, times, response);
  j["merge_s"] = seconds_since(t0);
  j["merge_cpu_s"] = cpu_seconds() - c0;
  j["peak_mb"] = peak_mb();
  j["log_rms"] = log_rms(s, hdr);
  std::printf("%s\n", j.dump().c_str());
}

template <typename Body>
void in_child(Body&& body) {
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    body();
    std::fflush(stdout);
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) std::fprintf(stderr, "bench_hdrmerge: an engine failed\n");
}

}  // namespace

int main(int argc, char** argv) {
  Setup s;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if (flag == "--width") s.width = v;
    else if (flag == "--height") s.height = v;
    else if (flag == "--exposures") s.exposures = v;
    else if (flag == "--threads") s.threads = v;
    else return std::fprintf(stderr, "usage: bench_hdrmerge [--width W] [--height H] [--exposures P] [--threads T]\n"), 2;
  }
  in_child([&] { run_fest(s); });
  in_child([&] { run_opencv(s); });
  return 0;
}
