#include "core/stack_budget.hpp"

#include <pthread.h>

#include <algorithm>

namespace fest {

std::ptrdiff_t usable_stack_bytes() {
  std::size_t size = 0;
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) == 0) {
    pthread_attr_getstacksize(&attr, &size);
    pthread_attr_destroy(&attr);
  }
  if (size == 0) return std::ptrdiff_t(4) << 20;
  constexpr std::size_t MiB = std::size_t(1) << 20;
  const std::size_t usable = size < 2 * MiB ? size / 2 : size - std::max(size / 8, MiB);
  return static_cast<std::ptrdiff_t>(std::min<std::size_t>(usable, std::size_t(1) << 30));
}

}  // namespace fest
