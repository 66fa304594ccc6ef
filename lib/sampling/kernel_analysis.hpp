#pragma once
// Kernel analysis for `resample kernel` (docs/resample.md): the frequency response at the
// pass-band and Nyquist probes, stop-band leakage, and the step response's over- and
// undershoot (the ringing that users see on edges).

#include <vector>

#include "sampling/kernel.hpp"

namespace fest::sampling {

struct KernelAnalysis {
  bool has_spatial = false;  // false for point sampling and the frequency-domain kernels
  double k_quarter = 0;      // K(0.25)
  double k_half = 0;         // K(0.5), the response at Nyquist
  double stop_max = 0;       // max |K(f)| over the stop band f >= 0.75
  double overshoot = 0;      // max of the step response minus 1 (0 for positive kernels)
  double undershoot = 0;     // minus the minimum of the step response
};

// Responses come from Simpson integration of k(x) with a 1e-4 px step (the kernel that
// resize applies, truncation included); kernels without a spatial form use their closed
// form. The stop band is scanned up to f = 3 in steps of 0.005 (beyond, every catalogue kernel is far below its maximum).
KernelAnalysis analyse_kernel(const Kernel& k);

// Tabulations for --csv: k(x) normalised to unit area at `count` points over
// [-radius, radius], and K(f) at `count` points over [0, f_max].
struct Curve {
  std::vector<double> x, y;
};
Curve kernel_curve(const Kernel& k, int count = 401);
Curve response_curve(const Kernel& k, double f_max = 2.0, int count = 401);

}  // namespace fest::sampling
