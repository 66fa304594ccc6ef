#pragma once
// Seeded random sources whose output is the same on every standard library (header
// only): xoshiro256** seeded through splitmix64 and an own Box-Muller transform, because
// std::normal_distribution differs between libraries and would break golden files.
// The project's one generator module: facefit's Rng is Rng; segbrain's phantom and
// compare's surface samples draw from SplitMix64 (their golden files were made with it).

#include <cmath>
#include <cstdint>

namespace fest {

// splitmix64's output for the state x (Steele, Lea & Flood 2014): a stateless 64-bit mix
// whose consecutive inputs give independent-looking outputs, for counter-based streams
// (a pixel's samples, a polygon's jittered points).
inline std::uint64_t splitmix64_mix(std::uint64_t x) {
  std::uint64_t z = x + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// SplitMix64 as a stream: the state advances by the golden-ratio increment and is mixed
// into the output. Seeds Rng; on its own a small, fast stream.
inline std::uint64_t splitmix64(std::uint64_t& state) {
  const std::uint64_t x = state;
  state += 0x9e3779b97f4a7c15ull;
  return splitmix64_mix(x);
}

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() { return splitmix64(state_); }  // 64 uniform bits
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }                // [0, 1)
  double uniform_open() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }  // (0, 1): the log stays finite
  double normal() {  // N(0, 1): Box-Muller's cosine half, two draws a number
    const double u1 = uniform_open();
    const double u2 = uniform_open();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * 3.14159265358979323846 * u2);
  }

 private:
  std::uint64_t state_;
};

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    for (auto& s : s_) s = splitmix64(seed);
  }
  std::uint64_t next() {  // 64 uniform bits
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  std::uint64_t below(std::uint64_t n) {  // uniform integer in [0, n)
    // Rejection keeps the result exactly uniform.
    const std::uint64_t limit = n == 0 ? 0 : (~std::uint64_t{0} - (~std::uint64_t{0} % n));
    std::uint64_t x;
    do x = next(); while (x >= limit);
    return x % n;
  }
  double normal() {  // N(0, 1)
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: the log stays finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * 3.14159265358979323846 * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace fest
