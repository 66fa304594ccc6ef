#include "wavelet/band_coder.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>

#include "core/error.hpp"
#include "wavelet/packed_coder.hpp"
#include "wavelet/range_coder.hpp"
#include "wavelet/rans.hpp"
#include "wavelet/slab_parts.hpp"

namespace fest::wavelet {

std::vector<Slab> slabs_of(const Subband& band) {
  std::vector<Slab> out;
  for (std::size_t z = band.lo[2]; z < band.hi[2]; z += kSlabPlanes)
    out.push_back({z, std::min(band.hi[2], z + kSlabPlanes)});
  return out;
}

const Subband* parent_of(const std::vector<Subband>& bands, const Subband& band) noexcept {
  if (band.orientation == 0) return nullptr;
  for (const auto& b : bands)
    if (b.orientation == band.orientation && b.level == band.level + 1) return &b;
  return nullptr;
}

namespace {

constexpr int kMagClasses = 16;
constexpr int kParentClasses = 3;
constexpr int kMaxExponent = 62;

int bit_width(std::uint64_t v) noexcept { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

// The context helpers below are written without branches: their inputs are the data,
// so a branch in them would be mispredicted about as often as the data surprises
// (callgrind's branch simulation counted 4.6 M such mispredictions in decoding the CT
// head at E = 1, a quarter of the decoder's).

// Neighbourhood activity -> one of kMagClasses classes: 0, 1, 2 exactly, then by octave
// (1 + bit_width(s), at most 15). Computed without a test on s: bit_width(2s + 1) - 1 is
// bit_width(s) for every s (no clz of zero; activities stay below 2^63 as exponents are
// at most 60), and 1 + bit_width(s) = bit_width(s) + (s >= 3) for s >= 3.
inline int activity_class(std::uint64_t s) noexcept {
  const int width = 63 - __builtin_clzll(2 * s + 1);
  return std::min(kMagClasses - 1, width + static_cast<int>(s >= 3));
}

inline std::uint64_t mag(std::int64_t v) noexcept {
  const std::uint64_t m = static_cast<std::uint64_t>(v >> 63);
  return (static_cast<std::uint64_t>(v) ^ m) - m;
}

inline int parent_class(std::uint64_t p) noexcept { return static_cast<int>(p != 0) + static_cast<int>(p >= 3); }

struct Models {
  std::array<BitModel, kMagClasses * kParentClasses> zero;
  std::array<std::array<BitModel, kMaxExponent + 1>, kMagClasses> exponent;
  std::array<BitModel, kMaxExponent + 1> second_bit;
  std::array<BitModel, 9> sign;
  std::array<BitModel, 4> zero_row;
};

inline int sign_of(std::int64_t v) noexcept { return static_cast<int>(v > 0) + 2 * static_cast<int>(v < 0); }

// Walks the slab in coding order, handing the coder each position with its contexts.
// Before each row, `skip_row(row0, width, context)` may code the row as all zero (one
// decision for a row of zeros instead of one per coefficient) and return true; the
// context says whether the rows at y-1 and z-1 were all zero.
template <typename SkipRow, typename Visit>
void walk(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent, const Slab& slab,
          const SkipRow& skip_row, const Visit& visit) {
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0];
  // Rows of zeros stand in for the neighbours outside the band or the slab, so the
  // inner loop has no branches for them.
  const std::vector<std::int64_t> zeros(w + 1, 0);
  std::vector<std::size_t> px(w, 0);
  if (parent)
    for (std::size_t k = 0; k < w; ++k) px[k] = std::min(parent->lo[0] + k / 2, parent->hi[0] - 1);
  const std::size_t h = band.hi[1] - band.lo[1];
  std::vector<std::uint8_t> zero_rows((slab.z1 - slab.z0) * h, 0);
  for (std::size_t z = slab.z0; z < slab.z1; ++z)
    for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
      const std::size_t row0 = band.lo[0] + y * sy + z * sz;
      const std::size_t r = (z - slab.z0) * h + (y - band.lo[1]);
      const int up_zero = y > band.lo[1] ? zero_rows[r - 1] : 1;
      const int back_zero = z > slab.z0 ? zero_rows[r - h] : 1;
      if (skip_row(row0, w, up_zero + 2 * back_zero)) {
        zero_rows[r] = 1;
        continue;
      }
      const std::int64_t* row = data + row0;
      const std::int64_t* up = y > band.lo[1] ? row - sy : zeros.data() + 1;
      const std::int64_t* back = z > slab.z0 ? row - sz : zeros.data() + 1;
      const std::int64_t* prow = nullptr;
      if (parent) {
        const std::size_t py = std::min(parent->lo[1] + (y - band.lo[1]) / 2, parent->hi[1] - 1);
        const std::size_t pz = std::min(parent->lo[2] + (z - band.lo[2]) / 2, parent->hi[2] - 1);
        prow = data + py * sy + pz * sz;
      }
      for (std::size_t k = 0; k < w; ++k) {
        const std::int64_t a = k > 0 ? row[k - 1] : 0;
        const std::int64_t b = up[k];
        const std::int64_t c = back[k];
        const std::int64_t d = k > 0 ? up[k - 1] : 0;
        const std::uint64_t p = prow ? mag(prow[px[k]]) : 0;
        const std::uint64_t activity = 2 * mag(a) + mag(b) + mag(c) + mag(d) / 2;
        const std::size_t pos[3] = {band.lo[0] + k, y, z};
        visit(row0 + k, pos, activity_class(activity), parent_class(p), 3 * sign_of(a) + sign_of(b), a, b, c, d);
      }
    }
}

// The prediction of an approximation coefficient: LOCO-I's median edge detector
// (JPEG-LS) from a = x-1, b = y-1, d = (x-1, y-1) inside the plane, else the first
// available neighbour. The result lies between neighbours, so it cannot overflow; and
// for float32 bit keys (monotone in the value) it is the key of the MED of the values.
std::int64_t approx_prediction(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d, const std::size_t* pos,
                               const Subband& band, const Slab& slab) {
  if (pos[0] > band.lo[0] && pos[1] > band.lo[1]) {
    const std::int64_t lo = std::min(a, b), hi = std::max(a, b);
    if (d >= hi) return lo;
    if (d <= lo) return hi;
    return a + (b - d);  // d lies strictly between a and b here
  }
  if (pos[0] > band.lo[0]) return a;
  if (pos[1] > band.lo[1]) return b;
  if (pos[2] > slab.z0) return c;
  return 0;
}

void put_raw(BitWriter& w, std::uint64_t value, int count) {
  if (count > 32) {
    w.put(value >> 32, count - 32);
    count = 32;
  }
  w.put(value, count);
}

// The token of a coefficient for the static coder: 0 for zero, 1 for |v| = 1, and
// 2e + (the bit below the leading one) for |v| with exponent e = floor(log2 |v|) >= 1:
// the zero flag, the unary exponent and the second bit of the adaptive coder in one
// symbol (at most 2 * 62 + 1 < kRansAlphabet).
inline int token_of(std::uint64_t m) noexcept {
  if (m == 0) return 0;
  const int e = bit_width(m) - 1;
  return e == 0 ? 1 : 2 * e + static_cast<int>((m >> (e - 1)) & 1);
}

// Tables of a static slab: tokens per (activity class, parent class), then the row
// flags per (y-1, z-1 row zero), then the signs per (x-1, y-1 signs).
constexpr int kTokenTables = kMagClasses * kParentClasses;
constexpr int kRowTables = 4;
constexpr int kSignTables = 9;
constexpr int kRowTable0 = kTokenTables, kSignTable0 = kTokenTables + kRowTables;
constexpr int kTables = kTokenTables + kRowTables + kSignTables;

const std::vector<int>& table_alphabets() {
  static const std::vector<int> a = [] {
    std::vector<int> v(kTables, 2);
    std::fill_n(v.begin(), kTokenTables, kRansAlphabet);
    return v;
  }();
  return a;
}

// Slab modes (the first byte of a slab's bytes; format version 3: 0 and 1, version 4
// adds 2).
constexpr char kAdaptiveSlab = 0, kStaticSlab = 1, kPackedSlab = 2;

// The static coding of a slab: the same walk and contexts as the adaptive one; the
// symbols go to two rANS streams (T: row flags and tokens, the next context waits for
// them; S: signs) and the low bits to the raw stream. Empty when some table cannot be
// written (normalise_table); the caller then keeps the adaptive coding.
std::string encode_static(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent,
                          const Slab& slab) {
  struct Event {
    std::uint8_t table, symbol;
  };
  std::vector<Event> tev, sev;
  BitWriter raw;
  std::vector<std::array<std::uint32_t, kRansAlphabet>> counts(kTables);
  for (auto& c : counts) c.fill(0);
  const bool approx = band.orientation == 0;
  auto skip_row = [&](std::size_t row0, std::size_t w, int ctx) {
    bool all_zero = true;
    for (std::size_t k = 0; k < w && all_zero; ++k) all_zero = data[row0 + k] == 0;
    tev.push_back({static_cast<std::uint8_t>(kRowTable0 + ctx), static_cast<std::uint8_t>(all_zero)});
    return all_zero;
  };
  walk(data, dims, band, parent, slab, skip_row,
       [&](std::size_t i, const std::size_t* pos, int mc, int pc, int sc, std::int64_t a, std::int64_t b, std::int64_t c,
           std::int64_t d) {
         std::int64_t v = data[i];
         if (approx) v -= approx_prediction(a, b, c, d, pos, band, slab);
         const std::uint64_t m = mag(v);
         const int t = token_of(m);
         tev.push_back({static_cast<std::uint8_t>(mc * kParentClasses + pc), static_cast<std::uint8_t>(t)});
         if (t == 0) return;
         const int e = bit_width(m) - 1;
         if (e >= 2) put_raw(raw, m, e - 1);
         sev.push_back({static_cast<std::uint8_t>(kSignTable0 + sc), static_cast<std::uint8_t>(v < 0)});
       });
  for (const auto& ev : tev) ++counts[ev.table][ev.symbol];
  for (const auto& ev : sev) ++counts[ev.table][ev.symbol];
  std::vector<RansTable> tables(kTables);
  for (int t = 0; t < kTables; ++t)
    if (!normalise_table(counts[static_cast<std::size_t>(t)].data(), table_alphabets()[static_cast<std::size_t>(t)],
                         tables[static_cast<std::size_t>(t)]))
      return {};
  BitWriter desc;
  write_tables(desc, tables, table_alphabets());
  auto code = [&](const std::vector<Event>& events) {
    RansEncoder enc;
    for (auto it = events.rbegin(); it != events.rend(); ++it) {
      const RansTable& tab = tables[it->table];
      enc.put(tab.cum[it->symbol], tab.freq[it->symbol]);
    }
    return enc.finish();
  };
  const std::string d = desc.finish(), t = code(tev), s = code(sev);
  std::string out(1, kStaticSlab);
  append_slab_parts(out, {d, t, s}, raw.finish());
  return out;
}

std::string encode_adaptive(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent,
                            const Slab& slab) {
  RangeEncoder enc, side;
  BitWriter raw;
  auto models = std::make_unique<Models>();
  const bool approx = band.orientation == 0;
  auto skip_row = [&](std::size_t row0, std::size_t w, int ctx) {
    bool all_zero = true;
    for (std::size_t k = 0; k < w && all_zero; ++k) all_zero = data[row0 + k] == 0;
    enc.encode(models->zero_row[static_cast<std::size_t>(ctx)], all_zero);
    return all_zero;
  };
  walk(data, dims, band, parent, slab, skip_row,
       [&](std::size_t i, const std::size_t* pos, int mc, int pc, int sc, std::int64_t a, std::int64_t b, std::int64_t c,
           std::int64_t d) {
         std::int64_t v = data[i];
         if (approx) v -= approx_prediction(a, b, c, d, pos, band, slab);
         enc.encode(models->zero[mc * kParentClasses + pc], v != 0);
         if (v == 0) return;
         const std::uint64_t mag = static_cast<std::uint64_t>(v < 0 ? -v : v);
         const int e = bit_width(mag) - 1;
         for (int k = 0; k < e; ++k) enc.encode(models->exponent[mc][k], 1);
         if (e < kMaxExponent) enc.encode(models->exponent[mc][e], 0);
         if (e >= 1) {
           side.encode(models->second_bit[e], static_cast<int>((mag >> (e - 1)) & 1));
           if (e >= 2) put_raw(raw, mag, e - 1);
         }
         side.encode(models->sign[sc], v < 0);
       });
  // Two parts and the raw bits (slab_parts.hpp): A holds the row flags, zero flags and
  // exponents (the decisions the next coefficient's context waits for), B the second
  // bits and signs.
  std::string out(1, kAdaptiveSlab);
  append_slab_parts(out, {enc.finish(), side.finish()}, raw.finish());
  return out;
}

}  // namespace

// Both context codings, the smaller kept (the static one on a tie: it decodes faster);
// then a packed coding instead (it decodes several times faster than either,
// docs/volwave.md §4 "Packed slabs"): with packed_slack 0, the smallest packed coding
// when it is not larger; above 0, the fastest within (1 + packed_slack) times the
// context coding's bytes -- without masks if that fits, else with them.
std::string encode_slab(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent,
                        const Slab& slab, SlabCoding coding, double packed_slack) {
  auto packed = [&](int masks) {
    std::string p = encode_packed_slab(data, dims, band, slab, masks, std::max(0.0, packed_slack));
    if (!p.empty()) p.insert(p.begin(), kPackedSlab);
    return p;
  };
  if (coding == SlabCoding::packed) {
    std::string p = packed(-1);
    if (!p.empty()) return p;
    coding = SlabCoding::smaller;
  }
  std::string fixed;
  if (coding != SlabCoding::adaptive) fixed = encode_static(data, dims, band, parent, slab);
  if (coding == SlabCoding::fixed && !fixed.empty()) return fixed;
  std::string best = encode_adaptive(data, dims, band, parent, slab);
  if (!fixed.empty() && fixed.size() <= best.size()) best = std::move(fixed);
  if (coding == SlabCoding::smaller && packed_slack >= 0 && band.orientation != 0) {
    const double budget = (1.0 + packed_slack) * static_cast<double>(best.size());
    auto fits = [&](const std::string& p) { return !p.empty() && static_cast<double>(p.size()) <= budget; };
    if (packed_slack == 0) {
      std::string p = packed(-1);
      if (fits(p)) return p;
    } else {
      // Dense unless masks save more than half the slack over it (sparse slabs: the
      // plume's dense slabs are ~1.5 times its masked ones, the heads' at E = 16 ~1.1).
      std::string dense = packed(0), masked = packed(1);
      const bool dense_ok = fits(dense), masked_ok = fits(masked);
      if (dense_ok && (!masked_ok || static_cast<double>(dense.size()) <=
                                         (1.0 + packed_slack / 2) * static_cast<double>(masked.size())))
        return dense;
      if (masked_ok) return masked;
    }
  }
  return best;
}

namespace {

[[noreturn]] void corrupt(const Subband& band, const Slab& slab) {
  throw bad_input("corrupt or truncated coefficient stream (level {} band {}, planes {}-{})", band.level,
                  band.orientation, slab.z0, slab.z1 - 1);
}

// The streams of a slab (append_slab_parts) and their decoders.
struct SlabStreams {
  std::string_view main, side, raw;
};
struct Decoders {
  RangeDecoder main, side;
  BitReader raw;
};

// The rows of a slab coded as holding a non-zero (zero_rows[r] == 0, r = (z - z0) * h +
// (y - y0)), as y + dims[1] * z: listed after the walk, not in it, so the walk's loop
// keeps its registers.
void list_nonzero_rows(const std::vector<std::uint8_t>& zero_rows, const Subband& band, const Slab& slab,
                       const Dims& dims, RowList& rows) {
  const std::size_t h = band.hi[1] - band.lo[1];
  for (std::size_t r = 0; r < zero_rows.size(); ++r)
    if (!zero_rows[r]) rows.push_back(band.lo[1] + r % h + dims[1] * (slab.z0 + r / h));
}

// The parent classes of a row's coefficients, from the parent row `prow` (decoded in an
// earlier chunk; it does not change while a slab decodes). Rows y and y+1 (y even) share
// a parent row, so the classes are computed at most once per two rows, outside the
// per-coefficient chain (CT head at E = 1: decode_slab 999 M -> 970 M instructions).
void update_parent_classes(const std::int64_t* prow, const std::vector<std::size_t>& px,
                           std::vector<std::uint8_t>& classes, const std::int64_t*& cached) {
  if (prow == cached) return;
  for (std::size_t k = 0; k < px.size(); ++k) classes[k] = static_cast<std::uint8_t>(parent_class(mag(prow[px[k]])));
  cached = prow;
}

// The decoder's walk: the same order and the same contexts as walk() + encode_slab,
// specialised for the band kind so the per-coefficient loop has no tests for it. The
// left neighbours a = x-1 and d = (x-1, y-1) are carried in registers from the previous
// coefficient; a corrupt exponent throws at once (the encoder never writes one).
// Returns false when a stream was read past its end. The decoders are local to the
// function (their address never escapes), so the compiler may keep their state in
// registers rather than reload it after every store of a coefficient.
template <bool Approx, bool HasParent>
bool decode_band_slab(const SlabStreams& streams, Models& models, std::int64_t* data, const Dims& dims, const Subband& band,
                      const Subband* parent, const Slab& slab, int limit, RowList& rows) {
  Decoders dec{RangeDecoder(streams.main), RangeDecoder(streams.side), BitReader(streams.raw)};
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0];
  const std::size_t h = band.hi[1] - band.lo[1];
  const std::vector<std::int64_t> zeros(w, 0);
  std::vector<std::size_t> px(HasParent ? w : 0);
  if (HasParent)
    for (std::size_t k = 0; k < w; ++k) px[k] = std::min(parent->lo[0] + k / 2, parent->hi[0] - 1);
  std::vector<std::uint8_t> parent_classes(HasParent ? w : 0);
  const std::int64_t* parent_row = nullptr;
  std::vector<std::uint8_t> zero_rows((slab.z1 - slab.z0) * h, 0);
  for (std::size_t z = slab.z0; z < slab.z1; ++z)
    for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
      const std::size_t row0 = band.lo[0] + y * sy + z * sz;
      std::int64_t* row = data + row0;
      {
        const std::size_t r = (z - slab.z0) * h + (y - band.lo[1]);
        const int up_zero = y > band.lo[1] ? zero_rows[r - 1] : 1;
        const int back_zero = z > slab.z0 ? zero_rows[r - h] : 1;
        if (dec.main.decode(models.zero_row[static_cast<std::size_t>(up_zero + 2 * back_zero)])) {
          zero_rows[r] = 1;  // the row is zero already (decode_slab's contract)
          continue;
        }
      }
      const std::int64_t* up = y > band.lo[1] ? row - sy : zeros.data();
      const std::int64_t* back = z > slab.z0 ? row - sz : zeros.data();
      if (HasParent) {
        const std::size_t py = std::min(parent->lo[1] + (y - band.lo[1]) / 2, parent->hi[1] - 1);
        const std::size_t pz = std::min(parent->lo[2] + (z - band.lo[2]) / 2, parent->hi[2] - 1);
        update_parent_classes(data + py * sy + pz * sz, px, parent_classes, parent_row);
      }
      std::int64_t a = 0, d = 0;
      for (std::size_t k = 0; k < w; ++k) {
        const std::int64_t b = up[k];
        const std::int64_t c = back[k];
        const std::uint64_t activity = 2 * mag(a) + mag(b) + mag(c) + mag(d) / 2;
        const int mc = activity_class(activity);
        const int pc = HasParent ? parent_classes[k] : 0;
        std::int64_t v = 0;
        if (dec.main.decode(models.zero[static_cast<std::size_t>(mc * kParentClasses + pc)])) {
          auto& exponent = models.exponent[static_cast<std::size_t>(mc)];
          int e = 0;
          while (e < kMaxExponent && dec.main.decode(exponent[static_cast<std::size_t>(e)])) ++e;
          if (e > limit) corrupt(band, slab);
          std::uint64_t m = 1;
          if (e >= 1) {
            m = (m << 1) | static_cast<std::uint64_t>(dec.side.decode(models.second_bit[static_cast<std::size_t>(e)]));
            // The raw bits, none for e = 1: no branch on that (it would be mispredicted
            // as often as e is).
            int count = e - 1;
            if (count > 32) {
              m = (m << (count - 32)) | dec.raw.get(count - 32);
              count = 32;
            }
            m = (m << count) | dec.raw.get(count);
          }
          const int sc = 3 * sign_of(a) + sign_of(b);
          v = dec.side.decode(models.sign[static_cast<std::size_t>(sc)]) ? -static_cast<std::int64_t>(m)
                                                                         : static_cast<std::int64_t>(m);
        }
        if (Approx) {
          const std::size_t pos[3] = {band.lo[0] + k, y, z};
          // The prediction is a neighbour already checked against the bound, so the
          // sum stays far inside int64.
          v += approx_prediction(a, b, c, d, pos, band, slab);
          if (bit_width(static_cast<std::uint64_t>(v < 0 ? -v : v)) - 1 > limit) corrupt(band, slab);
        }
        row[k] = v;
        a = v;
        d = b;
      }
    }
  list_nonzero_rows(zero_rows, band, slab, dims, rows);
  return !(dec.main.truncated() || dec.side.truncated() || dec.raw.overrun());
}

// The static slab's decoder: the walk of decode_band_slab, each coefficient one token
// from T (a table lookup chosen by the context), its low bits from R and its sign from S
// -- with the identity table when the token is zero, so no branch follows the data.
template <bool Approx, bool HasParent>
bool decode_static_slab(std::string_view tokens, std::string_view signs, std::string_view raw_bits,
                        const RansEntry* const* tab, const std::uint32_t* f0, std::int64_t* data, const Dims& dims, const Subband& band,
                        const Subband* parent, const Slab& slab, int limit, RowList& rows) {
  RansDecoder tdec(tokens), sdec(signs);
  BitReader raw(raw_bits);
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0];
  const std::size_t h = band.hi[1] - band.lo[1];
  const std::vector<std::int64_t> zeros(w, 0);
  std::vector<std::size_t> px(HasParent ? w : 0);
  if (HasParent)
    for (std::size_t k = 0; k < w; ++k) px[k] = std::min(parent->lo[0] + k / 2, parent->hi[0] - 1);
  std::vector<std::uint8_t> parent_classes(HasParent ? w : 0);
  const std::int64_t* parent_row = nullptr;
  std::vector<std::uint8_t> zero_rows((slab.z1 - slab.z0) * h, 0);
  for (std::size_t z = slab.z0; z < slab.z1; ++z)
    for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
      const std::size_t row0 = band.lo[0] + y * sy + z * sz;
      std::int64_t* row = data + row0;
      {
        const std::size_t r = (z - slab.z0) * h + (y - band.lo[1]);
        const int up_zero = y > band.lo[1] ? zero_rows[r - 1] : 1;
        const int back_zero = z > slab.z0 ? zero_rows[r - h] : 1;
        if (tdec.get_bit(f0[kRowTable0 + up_zero + 2 * back_zero])) {
          zero_rows[r] = 1;  // the row is zero already (decode_slab's contract)
          continue;
        }
      }
      const std::int64_t* up = y > band.lo[1] ? row - sy : zeros.data();
      const std::int64_t* back = z > slab.z0 ? row - sz : zeros.data();
      if (HasParent) {
        const std::size_t py = std::min(parent->lo[1] + (y - band.lo[1]) / 2, parent->hi[1] - 1);
        const std::size_t pz = std::min(parent->lo[2] + (z - band.lo[2]) / 2, parent->hi[2] - 1);
        update_parent_classes(data + py * sy + pz * sz, px, parent_classes, parent_row);
      }
      // The left neighbour's magnitude and sign and the up-left magnitude are carried
      // from the previous coefficient (a = x-1, d = (x-1, y-1)).
      std::int64_t a = 0, d = 0;
      std::uint64_t ma = 0, md = 0;
      int sa = 0;
      for (std::size_t k = 0; k < w; ++k) {
        const std::int64_t b = up[k];
        const std::int64_t c = back[k];
        const std::uint64_t mb = mag(b);
        const std::uint64_t activity = 2 * ma + mb + mag(c) + md / 2;
        const int mc = activity_class(activity);
        const int pc = HasParent ? parent_classes[k] : 0;
        const int t = tdec.get(tab[mc * kParentClasses + pc]);
        if (!Approx && t == 0) {
          // A zero: no sign, no raw bits. Zeros come in runs where the data is sparse,
          // so this branch is mostly predicted there; where the data is dense it is
          // rarely taken.
          row[k] = 0;
          a = 0;
          ma = 0;
          sa = 0;
          d = b;
          md = mb;
          continue;
        }
        const int e = t >> 1;
        if (e > limit) corrupt(band, slab);
        // t = 0, 1: the value itself; t >= 2: the leading one, the second bit, then
        // e - 1 raw bits (none below t = 4).
        std::uint64_t m = t < 2 ? static_cast<std::uint64_t>(t) : static_cast<std::uint64_t>(2 | (t & 1));
        int count = t < 4 ? 0 : e - 1;
        if (count > 32) {
          m = (m << (count - 32)) | raw.get(count - 32);
          count = 32;
        }
        m = (m << count) | raw.get(count);
        const int sc = 3 * sa + sign_of(b);
        const int negative = sdec.get_bit(t == 0 ? kRansTotal : f0[kSignTable0 + sc]);
        const std::uint64_t neg = 0 - static_cast<std::uint64_t>(negative);
        std::int64_t v = static_cast<std::int64_t>((m ^ neg) + static_cast<std::uint64_t>(negative));
        if (Approx) {
          const std::size_t pos[3] = {band.lo[0] + k, y, z};
          v += approx_prediction(a, b, c, d, pos, band, slab);
          if (bit_width(static_cast<std::uint64_t>(v < 0 ? -v : v)) - 1 > limit) corrupt(band, slab);
          m = mag(v);
          sa = sign_of(v);
        } else {
          sa = (t != 0) + negative;  // sign_of(v): 0, 1 positive, 2 negative
        }
        row[k] = v;
        a = v;
        ma = m;
        d = b;
        md = mb;
      }
    }
  list_nonzero_rows(zero_rows, band, slab, dims, rows);
  return tdec.done() && sdec.done() && !raw.overrun();
}

// A static slab: varint lengths of the table description D and the rANS streams T and
// S, then D, T, S and the raw bits to the end. Throws for anything no encoder writes.
void decode_static(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                   const Subband* parent, const Slab& slab, int limit, RowList& rows) {
  const auto parts = slab_parts<3>(bytes);
  if (!parts) corrupt(band, slab);
  BitReader desc((*parts)[0]);
  std::vector<RansTable> tables;
  if (!read_tables(desc, tables, table_alphabets())) corrupt(band, slab);
  const auto& alphabets = table_alphabets();
  // Token tables as lookup tables (one per context that has symbols); the binary ones
  // (row flags, signs) as the frequency of their 0 (kRansTotal when empty).
  std::size_t used = 0;
  for (int t = 0; t < kTokenTables; ++t) {
    const auto& f = tables[static_cast<std::size_t>(t)].freq;
    used += std::any_of(f.begin(), f.end(), [](auto v) { return v != 0; });
  }
  std::array<std::uint32_t, kTables> f0{};
  for (int t = kTokenTables; t < kTables; ++t) {
    const auto& f = tables[static_cast<std::size_t>(t)].freq;
    f0[static_cast<std::size_t>(t)] = f[0] == 0 && f[1] == 0 ? kRansTotal : f[0];
  }
  std::unique_ptr<RansEntry[]> storage(new RansEntry[std::max<std::size_t>(used, 1) * kRansTotal]);
  std::array<const RansEntry*, kTables> tab{};
  std::size_t next = 0;
  for (int t = 0; t < kTokenTables; ++t) {
    const RansTable& table = tables[static_cast<std::size_t>(t)];
    if (std::none_of(table.freq.begin(), table.freq.end(), [](auto f) { return f != 0; })) {
      tab[static_cast<std::size_t>(t)] = identity_decode_table();
      continue;
    }
    RansEntry* out = storage.get() + next * kRansTotal;
    fill_decode_table(table, alphabets[static_cast<std::size_t>(t)], out);
    tab[static_cast<std::size_t>(t)] = out;
    ++next;
  }
  const std::string_view tokens = (*parts)[1], signs = (*parts)[2], raw = (*parts)[3];
  bool ok;
  if (band.orientation == 0)
    ok = decode_static_slab<true, false>(tokens, signs, raw, tab.data(), f0.data(), data, dims, band, parent, slab, limit, rows);
  else if (parent)
    ok = decode_static_slab<false, true>(tokens, signs, raw, tab.data(), f0.data(), data, dims, band, parent, slab, limit, rows);
  else
    ok = decode_static_slab<false, false>(tokens, signs, raw, tab.data(), f0.data(), data, dims, band, parent, slab, limit, rows);
  if (!ok) corrupt(band, slab);
}

// Splits a slab's bytes into its three streams (append_slab_parts); throws for lengths that
// run past the slab.
SlabStreams split_streams(std::string_view bytes, const Subband& band, const Slab& slab) {
  const auto parts = slab_parts<2>(bytes);
  if (!parts) corrupt(band, slab);
  return SlabStreams{(*parts)[0], (*parts)[1], (*parts)[2]};
}

}  // namespace

void decode_slab(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                 const Subband* parent, const Slab& slab, int max_exponent, RowList* nonzero_rows,
                 int format_version) {
  const int limit = std::min(max_exponent, kMaxExponent);
  RowList local;
  RowList& rows = nonzero_rows ? *nonzero_rows : local;
  if (bytes.empty()) corrupt(band, slab);
  if (bytes[0] == kPackedSlab && format_version >= 4)
    return decode_packed_slab(bytes.substr(1), data, dims, band, slab, limit, rows, packed_avx2_available(),
                              format_version >= 5);
  if (bytes[0] != kAdaptiveSlab && bytes[0] != kStaticSlab) corrupt(band, slab);
  if (bytes[0] == kStaticSlab) return decode_static(bytes.substr(1), data, dims, band, parent, slab, limit, rows);
  const SlabStreams streams = split_streams(bytes.substr(1), band, slab);
  auto models = std::make_unique<Models>();
  bool ok;
  if (band.orientation == 0) ok = decode_band_slab<true, false>(streams, *models, data, dims, band, parent, slab, limit, rows);
  else if (parent) ok = decode_band_slab<false, true>(streams, *models, data, dims, band, parent, slab, limit, rows);
  else ok = decode_band_slab<false, false>(streams, *models, data, dims, band, parent, slab, limit, rows);
  if (!ok) corrupt(band, slab);
}

}  // namespace fest::wavelet
