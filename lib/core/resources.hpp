#pragma once
// What the machine can hold and what the process has used: sizes that follow from flags or
// headers (voxels of --size, pixels of --scale, frames of --t-end, a header's element
// count) checked against the memory this process may use, before anything is allocated --
// one line naming the size and the limit instead of "out of memory" half-way, or a process
// that grows until the system kills it; and the peak resident size the reports print.

#include <string>
#include <string_view>

#include "core/error.hpp"

namespace fest {

// Peak resident set size of this process in KiB (getrusage's ru_maxrss, which Linux
// reports in kilobytes).
long peak_rss_kb();

// Bytes this process may use at most: the physical memory, or the address-space limit
// (ulimit -v) where that is lower.
double memory_limit_bytes();

// "12.5 GB", "0.3 GB", "4e+15 bytes": plain numbers at every size.
std::string byte_text(double bytes);

// Throws Status `status` (usage: the size came from flags; bad_input: from a file) when
// `bytes` -- computed in double by the caller, so that no product overflows -- exceed the
// memory limit: "<what> needs 4e+15 bytes; this machine holds 24.6 GB".
void check_fits_in_memory(double bytes, std::string_view what, Status status = Status::usage);

}  // namespace fest
