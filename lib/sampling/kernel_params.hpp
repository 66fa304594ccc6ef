#pragma once
// Parameters of a kernel spelling "name:key=value,key=value" (docs/resample.md "Kernels and their responses").

#include <map>
#include <string>
#include <string_view>

namespace fest::sampling {

struct KernelSpelling {
  std::string name;                      // text before the first ':'
  std::string rest;                      // text after it (parameters, or dual's inner kernel)
};

// Splits at the first ':'.
KernelSpelling split_kernel_spelling(std::string_view spec);

// Parameter values by key, starting from `defaults`. Values are decimal numbers or
// fractions "p/q" (so `mitchell:b=1/3,c=1/3` reads as written in the literature).
// A key not in `defaults`, a malformed pair or a non-finite number is a usage error
// that names `kernel` and the accepted keys.
std::map<std::string, double> parse_kernel_params(std::string_view kernel, std::string_view text,
                                                  const std::map<std::string, double>& defaults);

}  // namespace fest::sampling
