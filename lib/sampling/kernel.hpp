#pragma once
// The kernel catalogue of resample (docs/resample.md "Kernels and their responses"): 1-D even kernels k(x) in units
// of output pixels, looked up by the names used on the command line
// ("name:key=value,key=value").

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fest::sampling {

struct Kernel {
  std::string name;  // canonical spelling with every parameter, e.g. "lanczos:a=3"
  // Support radius in output pixels: k(x) = 0 for |x| >= radius. Infinite for kernels that
  // exist only in the frequency domain (sinc/ideal, dual:*); 0 for point sampling.
  double radius = 0;
  bool interpolating = false;  // k(0) = 1 and k(n) = 0 at the other integers
  bool nearest = false;        // `point`: pick the nearest sample, no filtering
  // dual:R only: the spelling of the display's reconstruction filter R (resize correlates
  // with R, then applies the discrete inverse of R's sampled autocorrelation, docs/resample.md "The 1-D chain and the optimal prefilter").
  std::string reconstruction;
  // k(x), not normalised (resize normalises its weights; responses divide by K(0)).
  // Empty where the kernel has no finite spatial form (dual:*).
  std::function<double(double)> spatial;
  // K(f) with K(0) = 1 where a closed form exists (box, tent, bspline, the Gaussian spot,
  // ideal, dual:*); empty otherwise, and frequency_response() integrates `spatial`.
  std::function<double(double)> response;

  double operator()(double x) const { return spatial(x); }
};

// Looks up a kernel by its command-line spelling. Unknown names, unknown keys and
// out-of-range values throw fest::Error(Status::usage) naming what is accepted.
Kernel make_kernel(std::string_view spec);

// The names make_kernel accepts (without parameters), for messages and --help.
std::vector<std::string> kernel_names();

}  // namespace fest::sampling
