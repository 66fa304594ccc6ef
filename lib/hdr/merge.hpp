#pragma once
// Radiance merge of an exposure series through a known response (docs/hdrmerge.md §4):
//   ln E_i = sum_j w(Z_ij)(g(Z_ij) - ln dt_j) / sum_j w(Z_ij)
// computed with per-exposure lookup tables, in row bands on worker threads; no float
// copies of the exposures are made.

#include "core/progress_callback.hpp"
#include "hdr/debevec.hpp"
#include "hdr/stack.hpp"

namespace fest::hdr {

struct MergeResult {
  cv::Mat radiance;  // CV_32FC1 or CV_32FC3, relative radiance E (scale fixed by g(128) = 0)
  // CV_32FC1: fraction of the total hat weight the pixel received, min over channels,
  // in [0, 1]; 0 where some channel was black or saturated in every exposure. Such a
  // channel carries the estimate of the shortest exposure when its value there is in
  // the upper half of the range (saturated), else of the longest (black).
  cv::Mat valid;
};

// Throws bad_input for an invalid stack or a response with another channel count.
// `progress` hears the rows done of the calling thread's band (the bands are equal and run
// side by side, so it stands for the whole).
MergeResult merge_debevec(const ExposureStack& stack, const Response& response, int threads = 1,
                          const ProgressFn& progress = {});

}  // namespace fest::hdr
