#pragma once
// hdrmerge's side of the files: exposure times from flags, a series of images read
// through formats/image, response curves as CSV tables (z,gR,gG,gB or z,g).

#include <string>
#include <vector>

#include "core/progress_callback.hpp"
#include "core/table.hpp"
#include "hdr/debevec.hpp"
#include "hdr/stack.hpp"

namespace fest::hdrmerge_tool {

// "0.001", "1e-3", "1/1000" -> seconds. Throws usage_error for anything else.
double parse_exposure_time(const std::string& text);

// Reads every image (content-detected format) and pairs it with its time (seconds). Throws
// bad_input naming the file for unreadable or inconsistent images, and for a count
// mismatch between images and times.
// `progress` (may be empty) hears the images read of the series.
hdr::ExposureStack read_stack(const std::vector<std::string>& paths, const std::vector<double>& times,
                              const ProgressFn& progress = {});

Table response_table(const hdr::Response& response);
// Throws bad_input unless the table has 256 rows z = 0..255 and the g columns.
hdr::Response response_from_table(const Table& table);

}  // namespace fest::hdrmerge_tool
