#include "wavelet/packed_coder.hpp"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "core/cpu_features.hpp"
#include "core/error.hpp"
#include "wavelet/rans.hpp"
#include "wavelet/slab_parts.hpp"

namespace fest::wavelet {

namespace {

inline std::uint64_t mag(std::int64_t v) noexcept {
  const std::uint64_t m = static_cast<std::uint64_t>(v >> 63);
  return (static_cast<std::uint64_t>(v) ^ m) - m;
}

inline int bit_width(std::uint64_t v) noexcept { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

inline std::uint64_t load64(const std::uint8_t* p) noexcept {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;  // little-endian hosts only, like the rest of lib/wavelet's SIMD paths
}

// n <= 57 bits at bit position p (one unaligned load holds 57 bits past any bit offset).
inline std::uint64_t read_bits(const std::uint8_t* base, std::uint64_t p, int n) noexcept {
  return (load64(base + (p >> 3)) >> (p & 7)) & ((std::uint64_t{1} << n) - 1);
}
// Up to 64 bits: the low 32 first, as put_bits writes them.
inline std::uint64_t read_wide(const std::uint8_t* base, std::uint64_t p, int n) noexcept {
  if (n <= 57) return read_bits(base, p, n);
  return read_bits(base, p, 32) | (read_bits(base, p + 32, n - 32) << 32);
}

void put_bits(BitWriter& w, std::uint64_t value, int count) {
  if (count > 32) {
    w.put(value & 0xFFFFFFFFu, 32);
    w.put(value >> 32, count - 32);
    return;
  }
  w.put(value, count);
}

// For each 8-bit mask of non-zero lanes, the index of each lane's sign bit among the
// group's sign bits (the number of non-zero lanes before it), one byte per lane.
constexpr std::array<std::uint64_t, 256> make_prefix() {
  std::array<std::uint64_t, 256> t{};
  for (unsigned m = 0; m < 256; ++m) {
    std::uint64_t v = 0;
    unsigned count = 0;
    for (unsigned i = 0; i < 8; ++i) {
      v |= static_cast<std::uint64_t>(count) << (8 * i);
      count += (m >> i) & 1;
    }
    t[m] = v;
  }
  return t;
}
constexpr std::array<std::uint64_t, 256> kSignPrefix = make_prefix();

// Token contexts: s = 2 k_left + k_up + k_back (0..252) -> one of kPackContexts classes
// by one of three maps, which the slab names in its first byte (the encoder tries each
// and keeps the smallest slab): fine -- exact up to 11 (sparse data: which neighbours
// are zero or 1 bit wide), then in steps of two (dense data: the width drifts slowly),
// 24 classes; coarse -- 0, 1-2, 3-5, 6-11, 12-23, 24+, 6 classes; and one class. Small
// slabs cannot pay for 24 tables (their description, and the decoder's filling of a
// 2048-entry table per class: the plume's 45 packed slabs spent 2.8 M instructions
// filling tables with the fine map alone).
constexpr int kPackContexts = 24;
constexpr int kWidthAlphabet = 64;  // widths 0..63
constexpr int kContextMaps = 3;
constexpr std::array<std::array<std::uint8_t, 256>, kContextMaps> make_contexts() {
  std::array<std::array<std::uint8_t, 256>, kContextMaps> t{};
  for (int s = 0; s < 256; ++s) {
    const int fine = s < 12 ? s : 12 + (s - 12) / 2;
    t[0][static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(fine < kPackContexts - 1 ? fine : kPackContexts - 1);
    t[1][static_cast<std::size_t>(s)] =
        static_cast<std::uint8_t>(s == 0 ? 0 : s <= 2 ? 1 : s <= 5 ? 2 : s <= 11 ? 3 : s <= 23 ? 4 : 5);
    t[2][static_cast<std::size_t>(s)] = 0;
  }
  return t;
}
constexpr std::array<std::array<std::uint8_t, 256>, kContextMaps> kContextOf = make_contexts();

// The mask of a group's non-zero values (8 bits) as two 4-bit symbols, low half first,
// each with a table per width class (1, 2, 3-4, 5+) and half.
constexpr int kMaskTable0 = kPackContexts;
constexpr int kMaskTables = 8;
constexpr int kMaskAlphabet = 16;
constexpr std::array<std::uint8_t, 64> make_width_classes() {
  std::array<std::uint8_t, 64> t{};
  for (int k = 0; k < 64; ++k)
    t[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(k <= 1 ? 0 : k == 2 ? 1 : k <= 4 ? 2 : 3);
  return t;
}
constexpr std::array<std::uint8_t, 64> kWidthClass = make_width_classes();
constexpr int kRowTable0 = kMaskTable0 + kMaskTables;  // row flags per (y-1, z-1 row zero)
constexpr int kTables = kRowTable0 + 4;

const std::vector<int>& alphabets() {
  static const std::vector<int> a = [] {
    std::vector<int> v(kTables, 2);
    std::fill_n(v.begin(), kPackContexts, kWidthAlphabet);
    std::fill_n(v.begin() + kMaskTable0, kMaskTables, kMaskAlphabet);
    return v;
  }();
  return a;
}

// The first byte of a packed slab: the context map, masks or not, and (format version 5)
// the table precision, 11 - bits in [0, kPrecisionSteps).
constexpr int kPrecisionSteps = kRansBits - kRansMinBits + 1;
constexpr int packed_variant(int map, bool masked, int bits) noexcept {
  return map + kContextMaps * static_cast<int>(masked) + 2 * kContextMaps * (kRansBits - bits);
}

// Table precision for a slab decoded quickly: the decoder fills 2^bits entries per table
// with symbols, then decodes each symbol with one lookup (a few ns, against a fraction of
// a ns per entry filled). With 2^bits about four entries per symbol decoded, filling
// costs a fifth of the decoding at most; 2048 entries per table are kept where the slab
// has that many symbols per table (the heads' slabs), and lower precisions are what the
// plume's 35 small slabs need (280 tables of 2048 entries filled to decode ~20,000
// symbols). The row flags are read without a table and are not counted.
int fast_precision(const std::vector<std::array<std::uint32_t, kRansAlphabet>>& counts) noexcept {
  std::uint64_t symbols = 0;
  int tables = 0;
  for (int t = 0; t < kRowTable0; ++t) {
    std::uint64_t n = 0;
    for (std::uint32_t c : counts[static_cast<std::size_t>(t)]) n += c;
    symbols += n;
    tables += n > 0;
  }
  if (tables == 0) return kRansBits;
  int bits = kRansMinBits;
  while (bits < kRansBits && (std::uint64_t{1} << bits) * static_cast<std::uint64_t>(tables) < 4 * symbols) ++bits;
  return bits;
}

[[noreturn]] void corrupt(const Subband& band, const Slab& slab) {
  throw bad_input("corrupt or truncated coefficient stream (level {} band {}, planes {}-{}, packed)", band.level,
                  band.orientation, slab.z0, slab.z1 - 1);
}

}  // namespace

int pack_width(const std::int64_t* v, int n) noexcept {
  std::uint64_t m = 0;
  for (int i = 0; i < n; ++i) m |= mag(v[i]);
  return bit_width(m);
}

int pack_mask(const std::int64_t* v, int n) noexcept {
  int mask = 0;
  for (int i = 0; i < n; ++i) mask |= static_cast<int>(v[i] != 0) << i;
  return mask;
}

void pack_group(BitWriter& w, const std::int64_t* v, int n, int k, bool masked) {
  if (!masked) {
    if (k == 0) return;
    for (int i = 0; i < n; ++i) put_bits(w, mag(v[i]), k);
    for (int i = 0; i < n; ++i)
      if (v[i] != 0) w.put(v[i] < 0 ? 1 : 0, 1);
    return;
  }
  if (k <= 1) {
    if (k == 1)
      for (int i = 0; i < n; ++i)
        if (v[i] != 0) w.put(v[i] < 0 ? 1 : 0, 1);
    return;
  }
  for (int i = 0; i < n; ++i)
    if (v[i] != 0) put_bits(w, mag(v[i]), k);
  for (int i = 0; i < n; ++i)
    if (v[i] != 0) w.put(v[i] < 0 ? 1 : 0, 1);
}

namespace {

// The generic unpacking (any width, n <= 8 values): value i, when its mask bit is set,
// is the j-th magnitude (j = the set bits below i, from kSignPrefix) and has the j-th
// sign; without branches on the mask.
__attribute__((always_inline)) inline std::uint64_t unpack_generic(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                   int mask, int n, std::int64_t* out) noexcept {
  const int b = k - static_cast<int>(k == 1);  // magnitude bits: none for width 1
  const std::uint64_t one_bit = k == 1;
  const std::uint64_t pre = kSignPrefix[static_cast<std::size_t>(mask)];
  const int count = __builtin_popcount(static_cast<unsigned>(mask));
  const std::uint64_t sp = bp + static_cast<std::uint64_t>(count) * static_cast<unsigned>(b);
  const std::uint64_t signs = load64(base + (sp >> 3)) >> (sp & 7);
  for (int i = 0; i < n; ++i) {
    const unsigned j = static_cast<unsigned>(pre >> (8 * i)) & 0xFFu;
    const std::uint64_t nz = 0 - static_cast<std::uint64_t>((mask >> i) & 1);
    const std::uint64_t m = (read_wide(base, bp + j * static_cast<unsigned>(b), b) + one_bit) & nz;
    const std::uint64_t neg = (signs >> j) & 1;
    out[i] = static_cast<std::int64_t>((m ^ (0 - neg)) + neg);  // 0 stays 0 whatever neg
  }
  return sp + static_cast<std::uint64_t>(count);
}

}  // namespace

std::uint64_t unpack_partial(const std::uint8_t* base, std::uint64_t bp, int k, int mask, int n,
                             std::int64_t* out) noexcept {
  return unpack_generic(base, bp, k, mask, n, out);
}

std::uint64_t unpack_group_scalar(const std::uint8_t* base, std::uint64_t bp, int k, int mask,
                                  std::int64_t* out) noexcept {
  return unpack_generic(base, bp, k, mask, kPackGroup, out);
}

bool packed_avx2_available() noexcept { return cpu_has_avx2(); }

namespace {

// Four lanes per instruction: lane i's magnitude starts at bit bp + j_i b (j_i = the set
// mask bits below i, kSignPrefix), so a gather of the 64 bits at each start's byte, a
// variable shift and the width's mask give all of them; lanes whose mask bit is clear
// are zeroed; the sign of lane i is bit j_i of the sign bits.
__attribute__((target("avx2"))) inline std::uint64_t unpack8_avx2(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                 int mask, std::int64_t* out) noexcept {
  if (k > 57) return unpack_generic(base, bp, k, mask, kPackGroup, out);
  const int b = k - static_cast<int>(k == 1);
  const std::uint64_t pre = kSignPrefix[static_cast<std::size_t>(mask)];
  const __m256i j0 = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(pre & 0xFFFFFFFFu)));
  const __m256i j1 = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(pre >> 32)));
  const __m256i bb = _mm256_set1_epi64x(b);
  const __m256i start = _mm256_set1_epi64x(static_cast<long long>(bp));
  const __m256i p0 = _mm256_add_epi64(start, _mm256_mul_epu32(j0, bb));
  const __m256i p1 = _mm256_add_epi64(start, _mm256_mul_epu32(j1, bb));
  const __m256i seven = _mm256_set1_epi64x(7);
  const __m256i width = _mm256_set1_epi64x(static_cast<long long>((std::uint64_t{1} << b) - 1));
  const __m256i one_bit = _mm256_set1_epi64x(k == 1);
  const auto* src = reinterpret_cast<const long long*>(base);
  __m256i m0 = _mm256_i64gather_epi64(src, _mm256_srli_epi64(p0, 3), 1);
  __m256i m1 = _mm256_i64gather_epi64(src, _mm256_srli_epi64(p1, 3), 1);
  m0 = _mm256_add_epi64(_mm256_and_si256(_mm256_srlv_epi64(m0, _mm256_and_si256(p0, seven)), width), one_bit);
  m1 = _mm256_add_epi64(_mm256_and_si256(_mm256_srlv_epi64(m1, _mm256_and_si256(p1, seven)), width), one_bit);
  // Lane i keeps its value when mask bit i is set.
  const __m256i one = _mm256_set1_epi64x(1);
  const __m256i mv = _mm256_set1_epi64x(mask);
  const __m256i zero = _mm256_setzero_si256();
  const __m256i nz0 =
      _mm256_sub_epi64(zero, _mm256_and_si256(_mm256_srlv_epi64(mv, _mm256_setr_epi64x(0, 1, 2, 3)), one));
  const __m256i nz1 =
      _mm256_sub_epi64(zero, _mm256_and_si256(_mm256_srlv_epi64(mv, _mm256_setr_epi64x(4, 5, 6, 7)), one));
  m0 = _mm256_and_si256(m0, nz0);
  m1 = _mm256_and_si256(m1, nz1);
  const int count = __builtin_popcount(static_cast<unsigned>(mask));
  const std::uint64_t sp = bp + static_cast<std::uint64_t>(count) * static_cast<unsigned>(b);
  const __m256i sv = _mm256_set1_epi64x(static_cast<long long>(load64(base + (sp >> 3)) >> (sp & 7)));
  const __m256i n0 = _mm256_sub_epi64(zero, _mm256_and_si256(_mm256_srlv_epi64(sv, j0), one));
  const __m256i n1 = _mm256_sub_epi64(zero, _mm256_and_si256(_mm256_srlv_epi64(sv, j1), one));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_sub_epi64(_mm256_xor_si256(m0, n0), n0));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + 4), _mm256_sub_epi64(_mm256_xor_si256(m1, n1), n1));
  return sp + static_cast<std::uint64_t>(count);
}

}  // namespace

__attribute__((target("avx2"))) std::uint64_t unpack_group_avx2(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                int mask, std::int64_t* out) noexcept {
  return unpack8_avx2(base, bp, k, mask, out);
}

namespace {
// The signs after a dense group's n magnitudes m: one bit per non-zero magnitude, from bit
// bp on; writes the values and returns the position after the signs.
__attribute__((always_inline)) inline std::uint64_t apply_dense_signs(const std::uint8_t* base, std::uint64_t bp,
                                                                      const std::uint64_t* m, int n,
                                                                      std::int64_t* out) noexcept {
  const std::uint64_t signs = load64(base + (bp >> 3)) >> (bp & 7);
  int used = 0;
  for (int i = 0; i < n; ++i) {
    // neg for a zero magnitude reads some other value's bit, but (0 ^ -neg) + neg = 0.
    const std::uint64_t neg = (signs >> used) & 1;
    out[i] = static_cast<std::int64_t>((m[i] ^ (0 - neg)) + neg);
    used += m[i] != 0;
  }
  return bp + static_cast<std::uint64_t>(used);
}
}  // namespace

// Dense groups (a slab without masks): all n magnitudes in k bits, then a sign bit per
// non-zero one.
std::uint64_t unpack_dense_partial(const std::uint8_t* base, std::uint64_t bp, int k, int n,
                                   std::int64_t* out) noexcept {
  std::uint64_t m[kPackGroup];
  for (int i = 0; i < n; ++i) m[i] = read_wide(base, bp + static_cast<std::uint64_t>(i) * static_cast<unsigned>(k), k);
  bp += static_cast<std::uint64_t>(n) * static_cast<unsigned>(k);
  return apply_dense_signs(base, bp, m, n, out);
}

namespace {
__attribute__((always_inline)) inline std::uint64_t dense8_scalar(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                   std::int64_t* out) noexcept {
  if (k > 57) return unpack_dense_partial(base, bp, k, kPackGroup, out);
  std::uint64_t m[kPackGroup];
  const std::uint64_t mask = (std::uint64_t{1} << k) - 1;
  for (int i = 0; i < kPackGroup; ++i) {
    const std::uint64_t p = bp + static_cast<std::uint64_t>(i) * static_cast<unsigned>(k);
    m[i] = (load64(base + (p >> 3)) >> (p & 7)) & mask;
  }
  bp += static_cast<std::uint64_t>(kPackGroup) * static_cast<unsigned>(k);
  return apply_dense_signs(base, bp, m, kPackGroup, out);
}
}  // namespace

std::uint64_t unpack_dense_scalar(const std::uint8_t* base, std::uint64_t bp, int k, std::int64_t* out) noexcept {
  return dense8_scalar(base, bp, k, out);
}

// Dense, four lanes per instruction: the eight bit positions bp + i k, a gather of the 64 bits
// at each position's byte, a variable shift and the mask; the sign of lane i is bit
// (number of non-zero lanes before i) of the sign bits, from kSignPrefix.
namespace {
__attribute__((target("avx2"))) inline std::uint64_t dense8_avx2(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                std::int64_t* out) noexcept {
  if (k > 57) return unpack_dense_partial(base, bp, k, kPackGroup, out);
  const __m256i kk = _mm256_set1_epi64x(k);
  const __m256i p0 = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(bp)),
                                      _mm256_mul_epu32(_mm256_setr_epi64x(0, 1, 2, 3), kk));
  const __m256i p1 = _mm256_add_epi64(p0, _mm256_set1_epi64x(4LL * k));
  const __m256i seven = _mm256_set1_epi64x(7);
  const __m256i mask = _mm256_set1_epi64x(static_cast<long long>((std::uint64_t{1} << k) - 1));
  const auto* b = reinterpret_cast<const long long*>(base);
  __m256i m0 = _mm256_i64gather_epi64(b, _mm256_srli_epi64(p0, 3), 1);
  __m256i m1 = _mm256_i64gather_epi64(b, _mm256_srli_epi64(p1, 3), 1);
  m0 = _mm256_and_si256(_mm256_srlv_epi64(m0, _mm256_and_si256(p0, seven)), mask);
  m1 = _mm256_and_si256(_mm256_srlv_epi64(m1, _mm256_and_si256(p1, seven)), mask);
  const __m256i zero = _mm256_setzero_si256();
  const int z = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(m0, zero))) |
                (_mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(m1, zero))) << 4);
  const unsigned nz = ~static_cast<unsigned>(z) & 0xFFu;
  bp += static_cast<std::uint64_t>(kPackGroup) * static_cast<unsigned>(k);
  const std::uint64_t signs = load64(base + (bp >> 3)) >> (bp & 7);
  const std::uint64_t pre = kSignPrefix[nz];
  const __m256i sv = _mm256_set1_epi64x(static_cast<long long>(signs));
  const __m256i one = _mm256_set1_epi64x(1);
  const __m256i s0 = _mm256_and_si256(
      _mm256_srlv_epi64(sv, _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(pre & 0xFFFFFFFFu)))), one);
  const __m256i s1 = _mm256_and_si256(
      _mm256_srlv_epi64(sv, _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(pre >> 32)))), one);
  const __m256i n0 = _mm256_sub_epi64(zero, s0), n1 = _mm256_sub_epi64(zero, s1);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_sub_epi64(_mm256_xor_si256(m0, n0), n0));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + 4), _mm256_sub_epi64(_mm256_xor_si256(m1, n1), n1));
  return bp + static_cast<std::uint64_t>(__builtin_popcount(nz));
}
}  // namespace

__attribute__((target("avx2"))) std::uint64_t unpack_dense_avx2(const std::uint8_t* base, std::uint64_t bp, int k,
                                                                std::int64_t* out) noexcept {
  return dense8_avx2(base, bp, k, out);
}

std::string encode_packed_slab(const std::int64_t* data, const Dims& dims, const Subband& band, const Slab& slab,
                               int masks, double precision_slack) {
  if (band.orientation == 0) return {};
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0], h = band.hi[1] - band.lo[1];
  const std::size_t groups = (w + kPackGroup - 1) / kPackGroup;
  const std::size_t planes = slab.z1 - slab.z0;
  std::vector<std::uint8_t> widths(planes * h * groups, 0), zero_rows(planes * h, 0);
  const std::vector<std::uint8_t> no_widths(groups, 0);
  // A width token's event holds its s (the map picks the table later), the others their
  // table (fixed).
  struct Event {
    std::uint8_t s, symbol;
    bool fixed, mask;  // mask: in the second rANS stream M
  };
  std::vector<Event> events;
  BitWriter bits[2];  // without masks (dense groups), with masks
  for (std::size_t z = slab.z0; z < slab.z1; ++z)
    for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
      const std::size_t r = (z - slab.z0) * h + (y - band.lo[1]);
      const std::int64_t* row = data + band.lo[0] + y * sy + z * sz;
      const bool all_zero = std::all_of(row, row + w, [](std::int64_t v) { return v == 0; });
      const int up_zero = y > band.lo[1] ? zero_rows[r - 1] : 1;
      const int back_zero = z > slab.z0 ? zero_rows[r - h] : 1;
      events.push_back({static_cast<std::uint8_t>(kRowTable0 + up_zero + 2 * back_zero),
                        static_cast<std::uint8_t>(all_zero), true, false});
      if (all_zero) {
        zero_rows[r] = 1;
        continue;
      }
      const std::uint8_t* up = y > band.lo[1] ? &widths[(r - 1) * groups] : no_widths.data();
      const std::uint8_t* back = z > slab.z0 ? &widths[(r - h) * groups] : no_widths.data();
      std::uint8_t* mine = &widths[r * groups];
      int left = 0;
      for (std::size_t g = 0; g < groups; ++g) {
        const int n = static_cast<int>(std::min<std::size_t>(kPackGroup, w - g * kPackGroup));
        const int k = pack_width(row + g * kPackGroup, n);
        const int s = 2 * left + up[g] + back[g];
        events.push_back({static_cast<std::uint8_t>(s), static_cast<std::uint8_t>(k), false, false});
        mine[g] = static_cast<std::uint8_t>(k);
        left = k;
        if (k > 0) {
          const int mask = pack_mask(row + g * kPackGroup, n);
          const int c = kMaskTable0 + 2 * kWidthClass[static_cast<std::size_t>(k)];
          events.push_back({static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(mask & 15), true, true});
          events.push_back({static_cast<std::uint8_t>(c + 1), static_cast<std::uint8_t>(mask >> 4), true, true});
        }
        pack_group(bits[0], row + g * kPackGroup, n, k, false);
        pack_group(bits[1], row + g * kPackGroup, n, k, true);
      }
    }
  const std::string packed[2] = {bits[0].finish(), bits[1].finish()};
  // The symbol counts per table with one context map, with or without masks.
  using Counts = std::vector<std::array<std::uint32_t, kRansAlphabet>>;
  auto count = [&](const std::array<std::uint8_t, 256>& ctx, bool masked) {
    Counts counts(kTables);
    for (auto& c : counts) c.fill(0);
    for (const auto& e : events)
      if (masked || !e.mask) ++counts[e.fixed ? e.s : ctx[e.s]][e.symbol];
    return counts;
  };
  // Codes the events at one table precision; empty when a table cannot be written at it.
  auto code = [&](const Counts& counts, int map, bool masked, int precision) -> std::string {
    std::vector<RansTable> tables(kTables);
    for (int t = 0; t < kTables; ++t)
      if (!normalise_table(counts[static_cast<std::size_t>(t)].data(), alphabets()[static_cast<std::size_t>(t)],
                           tables[static_cast<std::size_t>(t)], precision))
        return {};
    BitWriter desc;
    write_tables(desc, tables, alphabets());
    // Two rANS states: widths and row flags (T), masks (M), so that a decoder's chain of
    // state updates through the masks runs beside the one through the widths.
    const auto& ctx = kContextOf[static_cast<std::size_t>(map)];
    RansEncoder enc(precision), menc(precision);
    for (auto it = events.rbegin(); it != events.rend(); ++it) {
      if (it->mask && !masked) continue;
      const RansTable& tab = tables[it->fixed ? it->s : ctx[it->s]];
      (it->mask ? menc : enc).put(tab.cum[it->symbol], tab.freq[it->symbol]);
    }
    const std::string d = desc.finish(), t = enc.finish(), m = menc.finish();
    std::string out(1, static_cast<char>(packed_variant(map, masked, precision)));
    append_slab_parts(out, {d, t, m}, packed[masked]);
    return out;
  };
  std::string best;
  for (int v = 0; v < 2 * kContextMaps; ++v) {
    const int map = v % kContextMaps;
    const bool masked = v >= kContextMaps;
    if (masks >= 0 && masked != (masks == 1)) continue;
    const Counts counts = count(kContextOf[static_cast<std::size_t>(map)], masked);
    std::string chosen = code(counts, map, masked, kRansBits);
    // A small slab also at a lower precision (docs/volwave.md §4, "Table precision"),
    // kept when at most (1 + precision_slack) times the bytes.
    const int fast = fast_precision(counts);
    if (fast < kRansBits) {
      std::string quick = code(counts, map, masked, fast);
      if (!quick.empty() && (chosen.empty() || static_cast<double>(quick.size()) <=
                                                   (1.0 + precision_slack) * static_cast<double>(chosen.size())))
        chosen = std::move(quick);
    }
    if (!chosen.empty() && (best.empty() || chosen.size() < best.size())) best = std::move(chosen);
  }
  return best;
}

namespace {

struct ScalarUnpack {
  static std::uint64_t group(const std::uint8_t* base, std::uint64_t bp, int k, int mask, std::int64_t* out) noexcept {
    return unpack_generic(base, bp, k, mask, kPackGroup, out);
  }
  static std::uint64_t dense(const std::uint8_t* base, std::uint64_t bp, int k, std::int64_t* out) noexcept {
    return dense8_scalar(base, bp, k, out);
  }
};
struct Avx2Unpack {
  __attribute__((target("avx2"))) static std::uint64_t group(const std::uint8_t* base, std::uint64_t bp, int k,
                                                             int mask, std::int64_t* out) noexcept {
    return unpack8_avx2(base, bp, k, mask, out);
  }
  __attribute__((target("avx2"))) static std::uint64_t dense(const std::uint8_t* base, std::uint64_t bp, int k,
                                                             std::int64_t* out) noexcept {
    return dense8_avx2(base, bp, k, out);
  }
};

struct PackedTables {
  const std::uint8_t* context_of = nullptr;  // s -> class (the slab's map)
  bool masked = false;                       // groups carry a mask of their non-zeros
  std::array<const RansEntry*, kPackContexts> token{};
  std::array<const RansEntry*, kMaskTables> mask{};
  std::array<std::uint32_t, 4> row_f0{};
};

// The rows of the slab: a row flag, then per group a width token and the group's bits.
// Returns false when a stream does not end where its bytes do. The rANS decoder is local
// (its address never escapes), so its state can stay in registers.
template <typename Unpack>
inline bool decode_rows(const PackedTables& tab, std::string_view tokens, std::string_view masks, int bits,
                        const std::uint8_t* base, std::uint64_t nbits, std::int64_t* data, const Dims& dims,
                        const Subband& band, const Slab& slab, int limit, std::vector<std::uint8_t>& zero_rows,
                        std::vector<std::uint8_t>& widths) {
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0], h = band.hi[1] - band.lo[1];
  const std::size_t full = w / kPackGroup, groups = (w + kPackGroup - 1) / kPackGroup;
  const int tail = static_cast<int>(w - full * kPackGroup);
  const std::size_t planes = slab.z1 - slab.z0;
  widths.assign(planes * h * groups + groups, 0);
  const std::uint8_t* no_widths = widths.data() + planes * h * groups;  // a row of zeros
  const int max_width = limit + 1;
  RansDecoder tdec(tokens, bits), mdec(masks, bits);
  std::uint64_t bp = 0;
  for (std::size_t z = slab.z0; z < slab.z1; ++z)
    for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
      const std::size_t r = (z - slab.z0) * h + (y - band.lo[1]);
      const int up_zero = y > band.lo[1] ? zero_rows[r - 1] : 1;
      const int back_zero = z > slab.z0 ? zero_rows[r - h] : 1;
      if (tdec.get_bit(tab.row_f0[static_cast<std::size_t>(up_zero + 2 * back_zero)])) {
        zero_rows[r] = 1;  // the row is zero already (decode_slab's contract)
        continue;
      }
      std::int64_t* row = data + band.lo[0] + y * sy + z * sz;
      const std::uint8_t* up = y > band.lo[1] ? &widths[(r - 1) * groups] : no_widths;
      const std::uint8_t* back = z > slab.z0 ? &widths[(r - h) * groups] : no_widths;
      std::uint8_t* mine = &widths[r * groups];
      int left = 0;
      for (std::size_t g = 0; g < groups; ++g) {
        const int s = 2 * left + up[g] + back[g];  // <= 4 * 63
        const int k = tdec.get(tab.token[tab.context_of[s]]);
        mine[g] = static_cast<std::uint8_t>(k);
        left = k;
        if (k == 0) continue;  // the positions are zero already
        // Checked per group, so the unpacking never reads past the padding.
        if (k > max_width || bp > nbits) return false;
        if (!tab.masked) {  // the same for the whole slab: predicted
          if (g < full) bp = Unpack::dense(base, bp, k, row + g * kPackGroup);
          else bp = unpack_dense_partial(base, bp, k, tail, row + g * kPackGroup);
          continue;
        }
        const RansEntry* const* mt = &tab.mask[2 * static_cast<std::size_t>(kWidthClass[static_cast<std::size_t>(k)])];
        const int lo = mdec.get(mt[0]);
        const int mask = lo | (mdec.get(mt[1]) << 4);
        if (g < full) {
          bp = Unpack::group(base, bp, k, mask, row + g * kPackGroup);
        } else {
          if (mask >> tail) return false;  // a value past the end of the row
          bp = unpack_generic(base, bp, k, mask, tail, row + g * kPackGroup);
        }
      }
    }
  return tdec.done() && mdec.done() && (bp + 7) / 8 == nbits / 8;
}

// flatten: everything inlined here, the AVX2 unpacking included (a template cannot carry
// the target, so the instantiation alone could not inline it).
__attribute__((target("avx2"), flatten)) bool decode_rows_avx2(
    const PackedTables& tab, std::string_view tokens, std::string_view masks, int bits, const std::uint8_t* base,
    std::uint64_t nbits, std::int64_t* data, const Dims& dims, const Subband& band, const Slab& slab, int limit,
    std::vector<std::uint8_t>& zero_rows, std::vector<std::uint8_t>& widths) {
  return decode_rows<Avx2Unpack>(tab, tokens, masks, bits, base, nbits, data, dims, band, slab, limit, zero_rows,
                                 widths);
}
__attribute__((flatten)) bool decode_rows_scalar(const PackedTables& tab, std::string_view tokens,
                                                 std::string_view masks, int bits, const std::uint8_t* base,
                                                 std::uint64_t nbits, std::int64_t* data, const Dims& dims,
                                                 const Subband& band, const Slab& slab, int limit,
                                                 std::vector<std::uint8_t>& zero_rows,
                                                 std::vector<std::uint8_t>& widths) {
  return decode_rows<ScalarUnpack>(tab, tokens, masks, bits, base, nbits, data, dims, band, slab, limit, zero_rows,
                                   widths);
}

// What decode_packed_slab needs besides the slab's bytes, kept between slabs.
struct PackedScratch {
  std::vector<RansTable> tables;
  std::vector<RansEntry> storage;
  std::vector<std::uint8_t> packed, zero_rows, widths;
};

// Makes v at least n long without shrinking it (a shrink and a regrow would zero-fill).
template <typename T>
void grow(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace

void decode_packed_slab(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                        const Slab& slab, int limit, RowList& rows, bool avx2, bool precision_allowed) {
  if (band.orientation == 0) corrupt(band, slab);  // never written for the approximation
  const int variant = bytes.empty() ? 255 : static_cast<std::uint8_t>(bytes[0]);
  if (variant >= 2 * kContextMaps * (precision_allowed ? kPrecisionSteps : 1)) corrupt(band, slab);
  PackedTables tab;
  tab.context_of = kContextOf[static_cast<std::size_t>(variant % kContextMaps)].data();
  tab.masked = variant % (2 * kContextMaps) >= kContextMaps;
  const int bits = kRansBits - variant / (2 * kContextMaps);
  const std::uint32_t entries = 1u << bits;
  const auto parts = slab_parts<3>(bytes.substr(1));
  if (!parts) corrupt(band, slab);
  BitReader desc((*parts)[0]);
  // The working storage of a slab, kept per thread: a small volume's decode is dozens of
  // slabs, and their allocations were 4 % of it.
  thread_local PackedScratch scratch;
  std::vector<RansTable>& tables = scratch.tables;
  if (!read_tables(desc, tables, alphabets(), bits)) corrupt(band, slab);
  // The width and mask tables as lookup tables (the ones that have symbols: a table
  // without any has the implied symbol's frequency 0).
  const auto& alpha = alphabets();
  auto has_symbols = [&](int t) {
    const RansTable& table = tables[static_cast<std::size_t>(t)];
    return table.freq[static_cast<std::size_t>(table.implied)] != 0;
  };
  std::size_t used = 0;
  for (int t = 0; t < kRowTable0; ++t) used += has_symbols(t);
  grow(scratch.storage, std::max<std::size_t>(used, 1) * entries);
  std::size_t next = 0;
  for (int t = 0; t < kRowTable0; ++t) {
    const RansEntry* e = identity_decode_table(bits);
    if (has_symbols(t)) {
      RansEntry* out = scratch.storage.data() + next * entries;
      fill_decode_table(tables[static_cast<std::size_t>(t)], alpha[static_cast<std::size_t>(t)], out);
      e = out;
      ++next;
    }
    if (t < kPackContexts) tab.token[static_cast<std::size_t>(t)] = e;
    else tab.mask[static_cast<std::size_t>(t - kMaskTable0)] = e;
  }
  for (int t = 0; t < 4; ++t) {
    const auto& f = tables[static_cast<std::size_t>(kRowTable0 + t)].freq;
    tab.row_f0[static_cast<std::size_t>(t)] = f[0] == 0 && f[1] == 0 ? entries : f[0];
  }
  const std::string_view tokens = (*parts)[1], masks = (*parts)[2], packed = (*parts)[3];
  // A copy with kPackSlack zero bytes after it: the unpacking loads 8 bytes at a time
  // without a test per value.
  std::vector<std::uint8_t>& buf = scratch.packed;
  grow(buf, packed.size() + kPackSlack);
  std::memcpy(buf.data(), packed.data(), packed.size());
  std::memset(buf.data() + packed.size(), 0, kPackSlack);
  const std::uint64_t nbits = 8 * static_cast<std::uint64_t>(packed.size());
  const std::size_t h = band.hi[1] - band.lo[1];
  std::vector<std::uint8_t>& zero_rows = scratch.zero_rows;
  zero_rows.assign((slab.z1 - slab.z0) * h, 0);
  const bool ok =
      avx2 && packed_avx2_available()
          ? decode_rows_avx2(tab, tokens, masks, bits, buf.data(), nbits, data, dims, band, slab, limit, zero_rows,
                             scratch.widths)
          : decode_rows_scalar(tab, tokens, masks, bits, buf.data(), nbits, data, dims, band, slab, limit, zero_rows,
                               scratch.widths);
  if (!ok) corrupt(band, slab);
  for (std::size_t r = 0; r < zero_rows.size(); ++r)
    if (!zero_rows[r]) rows.push_back(band.lo[1] + r % h + dims[1] * (slab.z0 + r / h));
}

}  // namespace fest::wavelet
