#pragma once
// Context-adaptive coding of the integer coefficients of one subband slab
// (docs/volwave.md §4). Each coefficient is coded as
//   zero?   -- context: the magnitudes of the already coded neighbours x-1, y-1, z-1,
//              (x-1, y-1) of the same band, and the parent (same orientation, next
//              coarser level, at half the position), which the decoder already has;
//   exponent e = floor(log2 |v|) in unary, each bit with its own adaptive model;
//   the bit below the leading one adaptively, the remaining e - 1 bits as they are;
//   the sign, modelled on the signs of the x-1 and y-1 neighbours.
// The approximation band codes v minus a prediction instead: the median edge detector
// of JPEG-LS (LOCO-I) from x-1, y-1 and (x-1, y-1), else the first available neighbour.
// Every band first says per row (x line) whether it is all zero, with a context from
// the rows at y-1 and z-1, and codes nothing more for such rows.
// A band is cut into slabs of kSlabPlanes z-planes, each coded independently, so
// slabs decode in parallel and a damaged stream spoils one slab only. A slab's bytes are
// a mode byte, then for an adaptive slab three streams: range-coded A (row flags, zero
// flags, exponents), range-coded B (second bits, signs) and the raw bits R; for a static
// slab the table description, two rANS streams T (row flags, tokens = zero flag,
// exponent and second bit in one symbol) and S (signs), and the raw bits R.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "wavelet/lifting.hpp"

namespace fest::wavelet {

constexpr std::size_t kSlabPlanes = 16;

// Slabs of a band: [z0, z1) ranges of absolute z.
struct Slab {
  std::size_t z0 = 0, z1 = 0;
};
std::vector<Slab> slabs_of(const Subband& band);

// The parent of a detail band (same orientation, one level coarser), or nullptr when
// the band's level is the coarsest.
const Subband* parent_of(const std::vector<Subband>& bands, const Subband& band) noexcept;

// How a slab is coded (its first byte says which): with the adaptive binary range coder,
// with static rANS tables counted for the slab and stored with it (format version 3), or
// packed (format version 4, packed_coder.hpp: a width per group of 8 coefficients, then
// their bits; detail bands only). `smaller` codes the two context codings and keeps the
// smaller (static on a tie), then takes the packed coding instead when its bytes are at
// most (1 + packed_slack) times that (packed_slack < 0: never); the others force one
// (packed falls back to `smaller` for the approximation band), for tests.
enum class SlabCoding { smaller, adaptive, fixed, packed };

// Codes the coefficients of `band` in the z-range of `slab`, read from the pyramid
// `data` (extent dims). `parent` may be null.
std::string encode_slab(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent,
                        const Slab& slab, SlabCoding coding = SlabCoding::smaller, double packed_slack = -1.0);

// Decodes a slab into `data`, whose positions in the slab must be zero on entry (rows
// coded as all zero are not written). Exponents above max_exponent, or a stream that
// ends too early, throw fest::Error(bad_input) naming the band. `nonzero_rows`, when
// given, gets the rows (y + dims[1] * z) coded as holding a non-zero appended: the
// inverse transform skips the others (lifting.hpp). `format_version`, the .vw file's:
// below 4 packed slabs are refused as corrupt, below 5 packed slabs stating a table
// precision below 11 bits.
void decode_slab(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                 const Subband* parent, const Slab& slab, int max_exponent, RowList* nonzero_rows = nullptr,
                 int format_version = 5);

}  // namespace fest::wavelet
