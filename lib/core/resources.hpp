#pragma once
// What the process has used so far, for the reports and benchmarks that print it.

namespace fest {

// Peak resident set size of this process in KiB (getrusage's ru_maxrss, which Linux
// reports in kilobytes).
long peak_rss_kb();

}  // namespace fest
