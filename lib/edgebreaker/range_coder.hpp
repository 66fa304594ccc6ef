#pragma once
// The range coder all .ebm sections share (docs/ebcode.md §4) is lib/core's
// (core/range_coder.hpp), with the stream ended by finish(): shortest, first byte implied.

#include "core/range_coder.hpp"

namespace fest::edgebreaker {

using range_coding::RangeDecoder;
using range_coding::RangeEncoder;
using range_coding::adapt_shift;
using range_coding::probability_bits;
using range_coding::probability_half;
using range_coding::range_top;

}  // namespace fest::edgebreaker
