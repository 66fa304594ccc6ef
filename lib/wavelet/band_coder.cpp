#include "wavelet/band_coder.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

#include "core/error.hpp"
#include "core/little_endian.hpp"
#include "wavelet/range_coder.hpp"

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

// Neighbourhood activity -> one of kMagClasses classes (0, 1, 2 exactly; then by octave).
inline int magnitude_class(std::uint64_t s) noexcept {
  const int octave_class = std::min(kMagClasses - 1, 1 + 64 - __builtin_clzll(s | 1));
  return s < 3 ? static_cast<int>(s) : octave_class;
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
        visit(row0 + k, pos, magnitude_class(activity), parent_class(p), 3 * sign_of(a) + sign_of(b), a, b, c, d);
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

// The three parts of a slab's stream: varint(length of A), varint(length of B), A, B,
// then the raw bits to the end. A holds the row flags, zero flags and exponents (the
// decisions the next coefficient's context waits for), B the second bits and signs.
std::string join_streams(const std::string& a, const std::string& b, const std::string& raw) {
  std::string out;
  little_endian::put_varint(out, a.size());
  little_endian::put_varint(out, b.size());
  out += a;
  out += b;
  out += raw;
  return out;
}

void put_raw(BitWriter& w, std::uint64_t value, int count) {
  if (count > 32) {
    w.put(value >> 32, count - 32);
    count = 32;
  }
  w.put(value, count);
}

}  // namespace

std::string encode_slab(const std::int64_t* data, const Dims& dims, const Subband& band, const Subband* parent,
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
  return join_streams(enc.finish(), side.finish(), raw.finish());
}

namespace {

[[noreturn]] void corrupt(const Subband& band, const Slab& slab) {
  throw bad_input("corrupt or truncated coefficient stream (level {} band {}, planes {}-{})", band.level,
                  band.orientation, slab.z0, slab.z1 - 1);
}

// The streams of a slab (join_streams) and their decoders.
struct SlabStreams {
  std::string_view main, side, raw;
};
struct Decoders {
  RangeDecoder main, side;
  BitReader raw;
};

// The decoder's walk: the same order and the same contexts as walk() + encode_slab,
// specialised for the band kind so the per-coefficient loop has no tests for it. The
// left neighbours a = x-1 and d = (x-1, y-1) are carried in registers from the previous
// coefficient; a corrupt exponent throws at once (the encoder never writes one).
// Returns false when a stream was read past its end. The decoders are local to the
// function (their address never escapes), so the compiler may keep their state in
// registers rather than reload it after every store of a coefficient.
template <bool Approx, bool HasParent>
bool decode_band_slab(const SlabStreams& streams, Models& models, std::int64_t* data, const Dims& dims, const Subband& band,
                      const Subband* parent, const Slab& slab, int limit) {
  Decoders dec{RangeDecoder(streams.main), RangeDecoder(streams.side), BitReader(streams.raw)};
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t w = band.hi[0] - band.lo[0];
  const std::size_t h = band.hi[1] - band.lo[1];
  const std::vector<std::int64_t> zeros(w, 0);
  std::vector<std::size_t> px(HasParent ? w : 0);
  if (HasParent)
    for (std::size_t k = 0; k < w; ++k) px[k] = std::min(parent->lo[0] + k / 2, parent->hi[0] - 1);
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
          std::fill_n(row, w, 0);
          zero_rows[r] = 1;
          continue;
        }
      }
      const std::int64_t* up = y > band.lo[1] ? row - sy : zeros.data();
      const std::int64_t* back = z > slab.z0 ? row - sz : zeros.data();
      const std::int64_t* prow = nullptr;
      if (HasParent) {
        const std::size_t py = std::min(parent->lo[1] + (y - band.lo[1]) / 2, parent->hi[1] - 1);
        const std::size_t pz = std::min(parent->lo[2] + (z - band.lo[2]) / 2, parent->hi[2] - 1);
        prow = data + py * sy + pz * sz;
      }
      std::int64_t a = 0, d = 0;
      for (std::size_t k = 0; k < w; ++k) {
        const std::int64_t b = up[k];
        const std::int64_t c = back[k];
        const std::uint64_t activity = 2 * mag(a) + mag(b) + mag(c) + mag(d) / 2;
        const int mc = magnitude_class(activity);
        const int pc = HasParent ? parent_class(mag(prow[px[k]])) : 0;
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
  return !(dec.main.truncated() || dec.side.truncated() || dec.raw.overrun());
}

// Splits a slab's bytes into its three streams (join_streams); throws for lengths that
// run past the slab.
SlabStreams split_streams(std::string_view bytes, const Subband& band, const Slab& slab) {
  std::size_t pos = 0;
  auto varint = [&]() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (pos >= bytes.size()) corrupt(band, slab);
      const auto byte = static_cast<std::uint8_t>(bytes[pos++]);
      v |= static_cast<std::uint64_t>(byte & 0x7F) << shift;
      if (!(byte & 0x80)) return v;
    }
    corrupt(band, slab);
  };
  const std::uint64_t la = varint(), lb = varint();
  if (la > bytes.size() - pos || lb > bytes.size() - pos - la) corrupt(band, slab);
  const std::string_view a = bytes.substr(pos, la), b = bytes.substr(pos + la, lb), r = bytes.substr(pos + la + lb);
  return SlabStreams{a, b, r};
}

}  // namespace

void decode_slab(std::string_view bytes, std::int64_t* data, const Dims& dims, const Subband& band,
                 const Subband* parent, const Slab& slab, int max_exponent) {
  const SlabStreams streams = split_streams(bytes, band, slab);
  auto models = std::make_unique<Models>();
  const int limit = std::min(max_exponent, kMaxExponent);
  bool ok;
  if (band.orientation == 0) ok = decode_band_slab<true, false>(streams, *models, data, dims, band, parent, slab, limit);
  else if (parent) ok = decode_band_slab<false, true>(streams, *models, data, dims, band, parent, slab, limit);
  else ok = decode_band_slab<false, false>(streams, *models, data, dims, band, parent, slab, limit);
  if (!ok) corrupt(band, slab);
}

}  // namespace fest::wavelet
