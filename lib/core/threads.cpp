#include "core/threads.hpp"

#include <sched.h>

#include <thread>

#include "core/error.hpp"

namespace fest {

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    int n = CPU_COUNT(&set);
    if (n > 0) return n;
  }
  unsigned hc = std::thread::hardware_concurrency();
  return hc > 0 ? static_cast<int>(hc) : 1;
}

int resolve_threads(int requested) {
  if (requested < 0) throw usage_error("a negative number of threads ({}); 0 means all cores", requested);
  if (requested > max_plausible_threads) throw usage_error("{} threads is not a plausible count", requested);
  return requested == 0 ? available_cores() : requested;
}

}  // namespace fest
