// fluidsim bench: stage timings per (size, solver, threads) -> JSON lines
// (fest::fluidsim::time_stages; tests/bench/bench_fluidsim runs the same without the tool).
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fluidsim/stage_bench.hpp"

namespace fest::fluidsim_tool {

int bench_command(const BenchOptions& o) {
  fluidsim::StageBenchOptions so;
  so.sizes = o.sizes;
  so.threads = o.threads;
  so.steps = o.steps;
  so.nu = o.nu;
  so.poisson = o.poisson;
  fluidsim::time_stages(so, [](const nlohmann::json& line) {
    std::printf("%s\n", line.dump().c_str());
    std::fflush(stdout);
  });
  return 0;
}

}  // namespace fest::fluidsim_tool
