// The operators' thread count (see parallel.hpp).
#include "segbrain/parallel.hpp"

#include <atomic>

namespace fest::segbrain {
namespace {
std::atomic<int> g_threads{1};
}

int worker_threads() { return g_threads.load(std::memory_order_relaxed); }
void set_worker_threads(int n) { g_threads.store(std::max(1, n), std::memory_order_relaxed); }

}  // namespace fest::segbrain
