#pragma once
// A contact sheet of radiance images for people to look at: every image scaled to a
// common tile width, tone-mapped with one exposure for the whole sheet (so relative
// brightness between tiles is kept) -- the 99th percentile of the non-zero radiance maps
// to 0.8 -- then encoded with the sRGB curve, and laid out in rows.

#include <vector>

#include <opencv2/core.hpp>

namespace fest::hdr {

// images: CV_32FC3 (R,G,B) or CV_32FC1. Returns CV_8UC3. Throws bad_input for an empty
// list or other types, usage_error for columns or tile_width < 1.
cv::Mat contact_sheet(const std::vector<cv::Mat>& images, int columns, int tile_width);

}  // namespace fest::hdr
