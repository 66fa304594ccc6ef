#pragma once
// Per-pixel sample patterns of `resample render` (docs/resample.md "Rendering analytic scenes"). Every pattern is a pure
// function of (pattern, N, seed, pixel): the samples of a pixel never depend on the order
// in which pixels are rendered, so output is bit-identical for any thread count.

#include <cstdint>
#include <string>
#include <vector>

namespace fest::sampling {

enum class Pattern { regular, jitter, random, rooks, rgss, poisson, halton, sobol };

struct Point2 {
  double x = 0, y = 0;  // in [0, 1)², relative to the pixel's corner
};

// "regular", "jitter", ...: usage error for other names.
Pattern parse_pattern(const std::string& name);
const char* pattern_name(Pattern p);

// Checks N for the pattern (regular and jitter need a square, rgss exactly 4, poisson at
// most 1024; 1..65536).
void check_sample_count(Pattern p, int n);

// The N samples of pixel (px, py).
std::vector<Point2> pixel_samples(Pattern p, int n, std::uint64_t seed, int px, int py);

// A 64-bit mix of its arguments (splitmix64 finaliser): the per-pixel random streams.
std::uint64_t hash64(std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0, std::uint64_t d = 0);

}  // namespace fest::sampling
