#pragma once
// The packed slab of a .vw detail band (format version 4, docs/volwave.md §4 "Packed
// slabs"): the fast-decoding alternative to the context coders of band_coder.cpp.
// Every row of the slab says first whether it is all zero (as in the other modes). A row
// that is not is cut into groups of kPackGroup consecutive coefficients; per group one
// static-rANS token gives its bit width k = bit_width(max |v|) (0: all zero), in a
// context of cheap neighbours -- the previous group's k in the row and the k of the
// groups at y-1 and z-1 -- then, for k > 0, two more give the mask of its non-zero
// values, and the non-zero magnitudes follow in k bits each (none for k = 1) and one sign
// bit each, in a plain bit stream. Decoding a group is three rANS steps and a fixed
// unpacking (a shift and a mask per coefficient, four at a time with AVX2 gathers):
// there is no per-coefficient context chain, which is what the context coders wait on.
//
// Bytes of a packed slab (after its mode byte): a variant byte (context map, masks or
// not), varint lengths of the table description D and the rANS streams T (row flags,
// widths) and M (masks), then D, T, M, and the packed bits P to the end (fest-vw(5)).
// A slab is packed either without masks (all magnitudes of a group in k bits: fastest
// to decode) or with them (smaller where groups are sparse); the encoder keeps what
// encode_slab's policy asks for.

#include <cstdint>
#include <string>
#include <string_view>

#include "wavelet/band_coder.hpp"
#include "wavelet/lifting.hpp"
#include "wavelet/range_coder.hpp"

namespace fest::wavelet {

constexpr int kPackGroup = 8;
// Readable bytes a decoder needs past the byte of a group's first bit: 8 magnitudes of
// up to 63 bits and 8 sign bits (65 bytes), plus the 8 of an unaligned 64-bit load.
constexpr std::size_t kPackSlack = 80;

// The width of a group: bit_width of its largest magnitude (0 when all are zero).
int pack_width(const std::int64_t* v, int n) noexcept;
// Bit i set when v[i] is non-zero (coded as two 4-bit rANS symbols).
int pack_mask(const std::int64_t* v, int n) noexcept;
// Appends the bits of n values of width k (|v| < 2^k): `masked` (the mask is coded in
// the rANS stream): the non-zero magnitudes in k bits each (none for k = 1: they are all
// 1); else all n magnitudes in k bits each; then a sign bit (1 = negative) per non-zero
// value, in order. Nothing for k = 0.
void pack_group(BitWriter& w, const std::int64_t* v, int n, int k, bool masked);

// Unpacks a group of kPackGroup values of width k (1..63) and non-zero mask `mask`
// starting at bit `bp` of `base` (bits low first, as BitWriter writes them) into
// out[0..8); `base` must be readable for kPackSlack bytes past bp / 8. Returns the bit
// position after the group. The scalar and AVX2 versions give the same values
// (unit-tested); the AVX2 one may only be called where packed_avx2_available().
std::uint64_t unpack_group_scalar(const std::uint8_t* base, std::uint64_t bp, int k, int mask,
                                  std::int64_t* out) noexcept;
std::uint64_t unpack_group_avx2(const std::uint8_t* base, std::uint64_t bp, int k, int mask,
                                std::int64_t* out) noexcept;
bool packed_avx2_available() noexcept;
// The same for a group of n < kPackGroup values (the end of a row; mask < 2^n).
std::uint64_t unpack_partial(const std::uint8_t* base, std::uint64_t bp, int k, int mask, int n,
                             std::int64_t* out) noexcept;
// The same for groups packed without a mask (dense slabs).
std::uint64_t unpack_dense_scalar(const std::uint8_t* base, std::uint64_t bp, int k, std::int64_t* out) noexcept;
std::uint64_t unpack_dense_avx2(const std::uint8_t* base, std::uint64_t bp, int k, std::int64_t* out) noexcept;
std::uint64_t unpack_dense_partial(const std::uint8_t* base, std::uint64_t bp, int k, int n,
                                   std::int64_t* out) noexcept;

// Codes a detail band's slab as a packed slab (without the mode byte): masks 0 without
// masks (dense groups: fastest to decode), 1 with them (smaller for sparse data), -1
// whichever is smaller; each with the smallest of the three context maps. A slab with
// few symbols per table is also coded at a lower table precision (format version 5;
// docs/volwave.md §4 "Table precision"), kept when at most (1 + precision_slack) times
// the bytes of full precision. Empty for the approximation band (its prediction needs
// the previous value: the context coders keep it) and when a token table cannot be
// written (normalise_table).
std::string encode_packed_slab(const std::int64_t* data, const Dims& dims, const Subband& band, const Slab& slab,
                               int masks = -1, double precision_slack = 0.0);

// Decodes what encode_packed_slab wrote into `data` (positions in the slab zero on
// entry), appends the rows coded as non-zero to `rows` (as decode_slab does), and
// throws fest::Error(bad_input) for anything no encoder writes: a width above
// limit + 1, streams too short or too long, a damaged table, a reduced table precision
// when `precision_allowed` is false (version 4 files). `avx2` picks the unpacker (the
// results are the same; false is for tests).
void decode_packed_slab(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                        const Slab& slab, int limit, RowList& rows, bool avx2 = packed_avx2_available(),
                        bool precision_allowed = true);

}  // namespace fest::wavelet
