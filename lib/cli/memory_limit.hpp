#pragma once
// Sizes that follow from flags (voxels of --size, pixels of --scale, frames of --t-end)
// checked against what this machine can hold, before anything is allocated: one line
// naming the size and the limit instead of "out of memory" half-way, or a process that
// grows until the system kills it. Light (no CLI11): tools' command files may include it.

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::cli {

// Bytes this process may use at most: the physical memory, or the address-space limit
// (ulimit -v) where that is lower.
inline double memory_limit_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  double limit = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0x1p40;
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    limit = std::min(limit, static_cast<double>(as.rlim_cur));
  return limit;
}

// "12.5 GB", "0.3 GB", "4e+15 bytes": plain numbers at every size.
inline std::string byte_text(double bytes) {
  if (bytes < 1e15) return fmt::format("{:.1f} GB", bytes / 1e9);
  return fmt::format("{:.3g} bytes", bytes);
}

// Throws Status `status` (usage: the size came from flags; bad_input: from a file) when
// `bytes` -- computed in double, so that no product overflows -- exceed the memory limit:
// "<what> needs 4e+15 bytes; this machine holds 24.6 GB".
inline void check_fits_in_memory(double bytes, std::string_view what, Status status = Status::usage) {
  const double limit = memory_limit_bytes();
  if (!(bytes <= limit))
    throw Error(status, fmt::format("{} needs {}; this machine holds {}", what, byte_text(bytes), byte_text(limit)));
}

}  // namespace fest::cli
