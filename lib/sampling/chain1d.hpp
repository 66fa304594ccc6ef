#pragma once
// The 1-D sampling-chain analysis behind `resample chain1d` (docs/resample.md "The 1-D chain and the optimal prefilter", Fig. 10.10):
// a unit cosine of frequency f is prefiltered by p, sampled at the integers and shown
// through the display's reconstruction filter r.

#include <optional>
#include <vector>

#include "sampling/kernel.hpp"

namespace fest::sampling {

struct ChainResult {
  double frequency = 0;   // f, cycles per sample
  double prefilter = 0;   // P(f)
  int terms = 0;          // K: components k = -K..K are summed
  // A_k = P(f) R(f - k) at frequency f - k, for k = -K..K (index k + K). A_0 is the
  // surviving original; the others are aliases.
  std::vector<double> amplitude;
  double survived = 0;    // A_0
  double alias_rms = 0;   // sqrt(Σ_{k≠0} A_k²)
  double mse = 0;         // |1 - A_0|² + Σ_{k≠0} A_k², relative to the signal's power
  double amplitude_at(int k) const { return amplitude.at(static_cast<std::size_t>(k + terms)); }
};

// K = 2000 is the default (docs/resample.md "The 1-D chain"); the tail beyond it changes the figures by < 1e-5 for
// a box display (Σ sinc² converges like 1/K) and far less for smoother displays.
ChainResult analyse_chain(const Kernel& prefilter, const Kernel& display, double f, int terms = 2000);

// Fig. 10.2: a unit step at x0 (or a bar [x0, x1]) is prefiltered with a box of width 2,
// sampled at the integers, linearly interpolated (tent of width 2) and thresholded at 0.5.
// Returns the positions where the reconstruction crosses 0.5, in increasing order.
std::vector<double> edge_experiment(double x0, std::optional<double> x1 = std::nullopt);

}  // namespace fest::sampling
