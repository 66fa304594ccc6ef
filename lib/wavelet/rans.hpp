#pragma once
// The static rANS coder of the .vw static slabs (docs/volwave.md §4) is lib/core's
// (core/rans.hpp, shared with .ebm 2.1's positions): its names in fest::wavelet, with
// the bit stream its tables are written to (range_coder.hpp).

#include "core/rans.hpp"
#include "wavelet/range_coder.hpp"

namespace fest::wavelet {

using range_coding::fill_decode_table;
using range_coding::identity_decode_table;
using range_coding::kRansAlphabet;
using range_coding::kRansBits;
using range_coding::kRansMinBits;
using range_coding::kRansLow;
using range_coding::kRansTotal;
using range_coding::normalise_table;
using range_coding::RansDecoder;
using range_coding::RansEncoder;
using range_coding::RansEntry;
using range_coding::RansTable;
using range_coding::read_tables;
using range_coding::write_tables;

}  // namespace fest::wavelet
