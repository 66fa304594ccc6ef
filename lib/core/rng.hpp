#pragma once
// The project's portable random generator (first written for facefit, lib/facefit/rng.hpp,
// moved here so that every domain draws from the same one).
// A seeded random source whose output is the same on every standard library:
// xoshiro256** seeded through splitmix64, and an own Box-Muller transform, because
// std::normal_distribution differs between libraries and would break golden files.

#include <cstdint>

namespace fest {

class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  std::uint64_t next();          // 64 uniform bits
  double uniform();              // [0, 1), 53 bits
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal();               // N(0, 1)
  std::uint64_t below(std::uint64_t n);  // uniform integer in [0, n)

 private:
  std::uint64_t s_[4];
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace fest
