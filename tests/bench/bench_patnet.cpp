// patnet's speed goals (docs/patnet.md "Performance"): 10,000 concurrent samp-fsm-like
// instances for 1,000 cycles (trace off, JSON to /dev/null, TSV to a file), loading a
// 1,000-line net file, and the memory of 10^5 idle instances. One JSON line per case.
// The figures are read against the goals; the same-run anchor (Qt SCXML's step rate) is
// bench_patnet_scxml.cpp, which needs Qt.

#include <chrono>
#include <ctime>
#include <cstdio>
#include <string>

#include "core/resources.hpp"
#include "patnet/machine.hpp"
#include "trace_writer.hpp"

using namespace fest;
using Clock = std::chrono::steady_clock;

namespace {

// samp-fsm (seed App. A §1) made endless: state4 resets the counters instead of exiting.
const char* looping = R"(
(defnet loop-fsm :locals '(a b)
  (definit (a b) (val a a) (val b b))
  (defaction :inca (val a (1+ (val a))))
  (defaction :incb (val b (1+ (val b))))
  (defaction :reset (val a 0) (val b 0))
  (defcond :c1 (< (val a) 6))
  (defcond :c2 (< (val b) 5))
  (defnode state1 :inca (:default state2))
  (defnode state2 :no-op (:c1 state1) (:default state3))
  (defnode state3 :incb (:default state4))
  (defnode state4 :no-op (:c2 state3) (:default state5))
  (defnode state5 :reset (:default state1)))
(dotimes (i 10000) (send loop-fsm :new (mod i 6) (mod i 5)))
)";

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void run_case(const char* name, patnet_tool::TraceFormat format, std::FILE* out) {
  patnet::RunOptions opt;
  opt.cycles = 1000;
  patnet_tool::TraceWriter writer(out, format);
  patnet::Machine m(opt, &writer);
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  m.load(looping, "loop.pat", true);
  const auto sum = m.run();
  writer.flush();
  std::fflush(out);
  const double s = seconds_since(t0);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  // CPU seconds too: on a shared machine the wall time includes other processes' turns.
  std::printf("{\"case\":\"%s\",\"instances\":%lld,\"cycles\":%lld,\"events\":%lld,\"seconds\":%.3f,"
              "\"cpu_seconds\":%.3f,\"instance_cycles_per_cpu_s\":%.4g,\"goal_seconds\":%g}\n",
              name, static_cast<long long>(sum.instances), static_cast<long long>(sum.cycles),
              static_cast<long long>(writer.events()), s, cpu, 1e7 / cpu,
              format == patnet_tool::TraceFormat::tsv ? 6.0 : 3.0);
  std::fflush(stdout);
}

}  // namespace

int main() {
  std::FILE* null = std::fopen("/dev/null", "w");
  run_case("10k_x_1000_trace_none", patnet_tool::TraceFormat::none, null);
  run_case("10k_x_1000_json_devnull", patnet_tool::TraceFormat::json, null);
  std::FILE* tmp = std::tmpfile();
  run_case("10k_x_1000_tsv_file", patnet_tool::TraceFormat::tsv, tmp);
  std::fclose(tmp);

  // A 1,000-line net file: 250 classes of four lines each.
  std::string big;
  for (int c = 0; c < 250; ++c)
    big += "(defnet n" + std::to_string(c) + " :locals '(a)\n  (defaction :go (val a (+ 1 (if (val a) (val a) 0))))\n"
           "  (defcond :more (< (val a) 3))\n  (defnode s1 :go (:more s1) (:default exit)))\n";
  const auto t1 = Clock::now();
  patnet::Machine probe;
  probe.load(big, "big.pat", false);
  probe.finish_checks();
  patnet::Machine m;
  m.load(big, "big.pat", true);
  std::printf("{\"case\":\"load_1000_lines\",\"lines\":1000,\"seconds\":%.4f,\"goal_seconds\":0.02}\n", seconds_since(t1));

  // Primitive calls per CPU second (goal >= 5 million): 3 x 10^6 calls of + and < in a loop.
  {
    patnet::RunOptions o;
    o.max_steps = 100000000;
    patnet::Machine calc(o, nullptr);
    const std::clock_t c0 = std::clock();
    calc.load("(setq s 0) (dotimes (i 1000000) (setq s (+ s (if (< i 5) 1 2) 1)))", "calls.pat", true);
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf("{\"case\":\"primitive_calls\",\"calls\":2000000,\"cpu_seconds\":%.3f,\"calls_per_cpu_s\":%.4g,\"goal_calls_per_s\":5e6}\n",
                cpu, 2e6 / cpu);
  }

  const long rss0 = peak_rss_kb();
  patnet::Machine idle;
  idle.load("(defnet idler :locals '(a b c) (defcond :never nil) (defnode s :no-op (:never s)))\n"
            "(dotimes (i 100000) (send idler :new))", "idle.pat", true);
  const long rss1 = peak_rss_kb();
  std::printf("{\"case\":\"memory_100k_idle\",\"instances\":100000,\"peak_rss_growth_mb\":%.1f,\"goal_mb\":100}\n",
              (rss1 - rss0) / 1024.0);
  std::fclose(null);
  return 0;
}
