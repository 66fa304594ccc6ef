#pragma once
// Camera response recovery after Robertson, Borman & Stevenson, "Dynamic range improvement
// through multiple exposures" (ICIP 1999), the alternative of docs/hdrmerge.md §3.
//
// Alternates two weighted least-squares steps on the linear inverse response I(z) = f^-1(z):
//   E_i = sum_j w(Z_ij) t_j I(Z_ij) / sum_j w(Z_ij) t_j^2        (radiance given I)
//   I(m) = mean of t_j E_i over all (i, j) with Z_ij = m          (I given radiance)
// normalising I(128) = 1 after each round, until the RMS change of ln I over the observed
// codes falls below `threshold` or `iterations` rounds have run. w is a Gaussian bump
// exp(-4 (z - 127.5)^2 / 127.5^2), zero within 4 of 0 and 255 (with noise, values next to
// the clipping points are biased); the curve is continued linearly in ln I there. The
// result is returned as g = ln I (g(128) = 0).

#include "hdr/debevec.hpp"
#include "hdr/stack.hpp"

namespace fest::hdr {

struct RobertsonOptions {
  // At most this many rounds. OpenCV stops at 30; the iteration creeps towards its fixed
  // point, 2.5 % worst error after 30 rounds on the test series, 1.7 % after 100.
  int iterations = 100;
  double threshold = 1e-5;  // RMS change of ln I between rounds
  int max_pixels = 200000;  // pixels used, on a regular grid (all pixels of small images)
};

// Throws bad_input for an invalid stack, usage_error for options out of range.
Response recover_response_robertson(const ExposureStack& stack, const RobertsonOptions& options = {});

}  // namespace fest::hdr
