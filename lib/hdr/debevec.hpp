#pragma once
// Camera response recovery after Debevec & Malik, "Recovering High Dynamic Range Radiance
// Maps from Photographs", SIGGRAPH 1997 (docs/hdrmerge.md §2).
//
// Unknowns g(z) = ln f^-1(z), z = 0..255, and ln E_i of N sample pixels; minimised:
//   sum_i sum_j [w(Z_ij)(g(Z_ij) - ln E_i - ln dt_j)]^2 + sum_z [lambda w(z) g''(z)]^2
// with g(128) = 0 fixing the free additive constant. lambda scales the smoothness rows
// as in the paper's gsolve listing and OpenCV's CalibrateDebevec (so lambda = 10 means
// the same there and here); in the paper's equation (3) that is lambda^2.

#include <array>
#include <vector>

#include "hdr/stack.hpp"

namespace fest::hdr {

using Curve = std::array<double, kCodes>;

// One curve per channel, g[c][128] == 0.
struct Response {
  std::vector<Curve> g;
  int channels() const { return int(g.size()); }
};

struct DebevecOptions {
  // N sample pixels per channel (N(P-1) must exceed Zmax - Zmin). OpenCV uses 70; with
  // 0.5 DN of noise that leaves the dark codes to 2-3 observations each and the curve
  // 3-6 % off there; 1000 keeps it within the 2 % that docs/hdrmerge.md §6 asks (about 30 ms per channel).
  int samples = 1000;
  double lambda = 10;   // smoothness weight
};

// Pixel positions (row-major linear indices) used as samples for one channel: a regular
// grid over the image, pixels without any well-exposed value (black or saturated in every
// image) left out, then N spread evenly over the values seen in the middle exposure so
// that the whole range of codes is covered.
std::vector<int> pick_samples(const ExposureStack& stack, int channel, int samples);

// Throws bad_input for an invalid stack or when too few usable samples remain
// (N(P-1) <= Zmax - Zmin), usage_error for options out of range.
Response recover_response_debevec(const ExposureStack& stack, const DebevecOptions& options = {});

}  // namespace fest::hdr
