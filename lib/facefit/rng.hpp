#pragma once
// facefit's random source is the project's one generator (lib/core/rng.hpp): xoshiro256**
// seeded through splitmix64 with an own Box-Muller transform, the same on every standard
// library, so golden files do not depend on it.

#include "core/rng.hpp"

namespace fest::facefit {

using Rng = fest::Rng;

}  // namespace fest::facefit
