// bench_fluidsim: `fluidsim bench` without the tool. It links lib/fluidsim alone, so its
// shared libraries are FFTW, OpenMP, {fmt} and the C++ runtime: the binary that
// tests/bench/fluidsim_device.sh packs with them for a machine that has none of the
// Debian packages (issue 23's 4- and 16-thread scaling). One JSON line per stage.
//
//   bench_fluidsim [--sizes 64,128] [--threads 1,2,4,8,16] [--steps 5] [--nu 1e-4] [--poisson fdm,fft]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fluidsim/stage_bench.hpp"

namespace {

using fest::fluidsim::PoissonSolver;

std::vector<std::string> split(const char* text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr, "bench_fluidsim: %s\nusage: bench_fluidsim [--sizes N,...] [--threads T,...] [--steps S] "
               "[--nu X] [--poisson fdm,fft,mg,gs,jacobi]\n", why);
  std::exit(2);
}

int whole(const std::string& s, int lo, int hi) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || v < lo || v > hi) usage(("not a whole number from " + std::to_string(lo) + " to " +
                                                            std::to_string(hi) + ": " + s).c_str());
  return static_cast<int>(v);
}

PoissonSolver solver(const std::string& name) {
  for (PoissonSolver s : {PoissonSolver::fdm, PoissonSolver::fft, PoissonSolver::mg, PoissonSolver::gs,
                          PoissonSolver::jacobi})
    if (name == fest::fluidsim::poisson_name(s)) return s;
  usage(("unknown solver: " + name).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  fest::fluidsim::StageBenchOptions o;
  for (int i = 1; i < argc; ++i) {
    const char* flag = argv[i];
    if (i + 1 >= argc) usage((std::string("missing value after ") + flag).c_str());
    const char* value = argv[++i];
    if (std::strcmp(flag, "--sizes") == 0) {
      o.sizes.clear();
      for (const std::string& s : split(value)) o.sizes.push_back(whole(s, 3, 1024));
    } else if (std::strcmp(flag, "--threads") == 0) {
      o.threads.clear();
      for (const std::string& s : split(value)) o.threads.push_back(whole(s, 1, 1024));
    } else if (std::strcmp(flag, "--steps") == 0) {
      o.steps = whole(value, 1, 100000);
    } else if (std::strcmp(flag, "--nu") == 0) {
      char* end = nullptr;
      o.nu = std::strtod(value, &end);
      if (*end != '\0' || !(o.nu >= 0 && o.nu <= 1)) usage("--nu takes a number from 0 to 1");
    } else if (std::strcmp(flag, "--poisson") == 0) {
      o.poisson.clear();
      for (const std::string& s : split(value)) o.poisson.push_back(solver(s));
    } else {
      usage((std::string("unknown option ") + flag).c_str());
    }
  }
  if (o.sizes.empty() || o.threads.empty() || o.poisson.empty()) usage("empty list");
  fest::fluidsim::time_stages(o, [](const nlohmann::json& line) {
    std::printf("%s\n", line.dump().c_str());
    std::fflush(stdout);
  });
  return 0;
}
