#pragma once
// The callback type alone, for headers that take a ProgressFn without counting anything
// themselves (formats/ writers): <functional> only. core/progress_callback.hpp has the
// counters built on it.
#include <cstdint>
#include <functional>

namespace fest {

// (steps done, steps in all); an empty ProgressFn means nobody listens.
using ProgressFn = std::function<void(std::uint64_t done, std::uint64_t total)>;

}  // namespace fest
