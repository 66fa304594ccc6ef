// The .vw codec: the L-infinity bound on every voxel, bit-exact lossless coding,
// truncation to coarser volumes with the stated error, and damaged input refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <cstring>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "wavelet/range_coder.hpp"
#include "wavelet/quantiser.hpp"
#include "wavelet/vw_codec.hpp"

using namespace fest;
using namespace fest::wavelet;

namespace {

// A smooth blob plus noise, as `type`.
Volume test_volume(ScalarType type, std::size_t nx = 23, std::size_t ny = 17, std::size_t nz = 11, double noise = 3.0) {
  Volume v;
  v.resize(nx, ny, nz);
  v.type = type;
  v.spacing = {0.5, 0.7, 1.2};
  v.origin = {-3, 4, 5};
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, noise);
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x) {
        const double r2 = std::pow(x - nx / 2.0, 2) + std::pow(y - ny / 2.0, 2) + std::pow(z - nz / 2.0, 2);
        double val = 100.0 + 900.0 * std::exp(-r2 / 40.0) + g(rng);
        if (scalar_type_is_integer(type)) val = std::round(val);
        if (type == ScalarType::f32) val = static_cast<double>(static_cast<float>(val));
        v.at(x, y, z) = val;
      }
  return v;
}

// Keys the AVX2 dequantisers must send the scalar way or treat with care: around +-2^51
// (where the exact conversion through the 2^52 + 2^51 bias stops) and far past it.
constexpr std::int64_t kEdgeKey = std::int64_t{1} << 51;
constexpr std::int64_t kSpecialKeys[] = {0, 1, -1, kEdgeKey - 1, -kEdgeKey + 1, kEdgeKey, -kEdgeKey, kEdgeKey + 1,
                                         -kEdgeKey - 1, std::numeric_limits<std::int64_t>::max() / 4,
                                         -(std::int64_t{1} << 60)};

// The values of `keys` by dequantise and by dequantise_in_place (first and second).
std::pair<std::vector<double>, std::vector<double>> dequantise_both_ways(const std::vector<std::int64_t>& keys,
                                                                         const Quantiser& q, ScalarType type) {
  std::vector<double> got;
  dequantise(keys, q, type, got, 1);
  std::vector<double> in_place(keys.size());
  if (!keys.empty()) std::memcpy(in_place.data(), keys.data(), 8 * keys.size());  // data() may be null when empty
  dequantise_in_place(in_place.data(), keys.size(), q, type, 1);
  return {got, in_place};
}

double max_abs(const Volume& a, const Volume& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.voxels.size(); ++i) m = std::max(m, std::fabs(a.voxels[i] - b.voxels[i]));
  return m;
}

}  // namespace

TEST(WaveletCodec, RangeCoderAndBitStreamRoundTrip) {
  // A slab's streams: modelled decisions in the range coder, the raw low bits of
  // magnitudes (0 to 32 of them at a time) in the bit stream beside it.
  std::mt19937_64 rng(1);
  std::vector<int> bits(5000);
  for (auto& b : bits) b = (rng() % 10) < 2;
  std::vector<std::pair<std::uint64_t, int>> raw(3000);
  for (auto& r : raw) {
    r.second = static_cast<int>(rng() % 33);
    r.first = rng() & ((std::uint64_t{1} << r.second) - 1);
  }
  RangeEncoder enc;
  BitWriter bw;
  BitModel m;
  for (int b : bits) enc.encode(m, b);
  for (const auto& r : raw) bw.put(r.first, r.second);
  const std::string bytes = enc.finish(), rbytes = bw.finish();
  RangeDecoder dec(bytes);
  BitReader br(rbytes);
  BitModel m2;
  for (std::size_t i = 0; i < bits.size(); ++i) ASSERT_EQ(dec.decode(m2), bits[i]) << i;
  for (std::size_t i = 0; i < raw.size(); ++i) ASSERT_EQ(br.get(raw[i].second), raw[i].first) << i;
  EXPECT_FALSE(dec.truncated());
  EXPECT_FALSE(br.overrun());
  // Reading past the end is seen, and yields zeros.
  EXPECT_EQ(br.get(9), 0u);  // the last byte has at most 7 bits of padding
  EXPECT_TRUE(br.overrun());
  RangeDecoder cut(std::string_view(bytes).substr(0, bytes.size() / 2));
  BitModel m3;
  for (std::size_t i = 0; i < bits.size(); ++i) (void)cut.decode(m3);
  EXPECT_TRUE(cut.truncated());
}

TEST(WaveletCodec, MaxErrorHoldsOnEveryVoxel) {
  for (ScalarType type : {ScalarType::u16, ScalarType::i16, ScalarType::f32, ScalarType::f64}) {
    const Volume v = test_volume(type);
    for (double bound : {0.25, 1.0, 2.5, 10.0}) {
      for (Wavelet w : {Wavelet::haar, Wavelet::cdf53}) {
        EncodeOptions o;
        o.bound = bound;
        o.wavelet = w;
        EncodeStats st;
        const std::string bytes = encode_vw(v, o, &st);
        const DecodeResult d = decode_vw(bytes, 2);
        EXPECT_LE(max_abs(v, d.volume), bound) << scalar_type_name(type) << " " << bound;
        EXPECT_FALSE(d.truncated);
        EXPECT_EQ(d.volume.dims, v.dims);
        EXPECT_EQ(d.volume.spacing, v.spacing);
        EXPECT_EQ(d.volume.type, v.type);
        EXPECT_DOUBLE_EQ(d.max_error, st.max_error);
      }
    }
  }
}

TEST(WaveletCodec, IntegerBoundUsesOddSteps) {
  // Integer data with bound 1: step 3, so every error is -1, 0 or 1, and some are 1.
  const Volume v = test_volume(ScalarType::i16);
  EncodeOptions o;
  o.bound = 1.0;
  EncodeStats st;
  const DecodeResult d = decode_vw(encode_vw(v, o, &st));
  EXPECT_EQ(st.step, 3.0);
  EXPECT_EQ(max_abs(v, d.volume), 1.0);
}

TEST(WaveletCodec, LosslessIsBitExact) {
  for (ScalarType type : {ScalarType::u8, ScalarType::u16, ScalarType::i16, ScalarType::f32}) {
    Volume v = test_volume(type == ScalarType::u8 ? ScalarType::u16 : type);
    v.type = type;
    if (type == ScalarType::u8)
      for (auto& x : v.voxels) x = std::min(255.0, std::max(0.0, x / 4));
    if (type == ScalarType::f32) {
      v.voxels[3] = std::numeric_limits<double>::quiet_NaN();
      v.voxels[4] = -0.0;
      v.voxels[5] = static_cast<double>(static_cast<float>(1e-40));  // a float32 subnormal
      for (std::size_t i = 6; i < v.voxels.size(); i += 7) v.voxels[i] = static_cast<float>(v.voxels[i] * 1.0001);
    } else {
      for (auto& x : v.voxels) x = std::round(x);
    }
    EncodeOptions o;
    o.mode = Mode::lossless;
    const DecodeResult d = decode_vw(encode_vw(v, o));
    for (std::size_t i = 0; i < v.voxels.size(); ++i) {
      const double a = v.voxels[i], b = d.volume.voxels[i];
      if (std::isnan(a)) {
        EXPECT_TRUE(std::isnan(b));
        continue;
      }
      ASSERT_EQ(std::memcmp(&a, &b, 8), 0) << scalar_type_name(type) << " voxel " << i << ": " << a << " vs " << b;
    }
    EXPECT_EQ(d.max_error, 0.0);
  }
}

TEST(WaveletCodec, Float64ThatFloat32CannotHoldIsRefusedLossless) {
  Volume v = test_volume(ScalarType::f64);
  v.voxels[0] = 0.1;
  EncodeOptions o;
  o.mode = Mode::lossless;
  try {
    encode_vw(v, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
  }
}

TEST(WaveletCodec, NanWithABoundIsBadInput) {
  Volume v = test_volume(ScalarType::f32);
  v.voxels[10] = std::numeric_limits<double>::quiet_NaN();
  EncodeOptions o;
  o.bound = 1;
  try {
    encode_vw(v, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos);
  }
  o.bound = 0;
  EXPECT_THROW(encode_vw(test_volume(ScalarType::f32), o), Error);
  o.bound = -1;
  EXPECT_THROW(encode_vw(test_volume(ScalarType::f32), o), Error);
}

TEST(WaveletCodec, TruncatedFilesDecodeCoarserWithTheStatedError) {
  const Volume v = test_volume(ScalarType::f32, 40, 36, 20);
  EncodeOptions o;
  o.bound = 0.5;
  const std::string bytes = encode_vw(v, o);
  const VwHeader h = read_vw_header(bytes);
  ASSERT_GE(h.levels, 2);
  std::size_t end = h.header_bytes;
  double previous = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < h.chunks.size(); ++k) {
    end += h.chunks[k].bytes;
    // Cut in the middle of the next chunk: only chunks 0..k are complete.
    const std::size_t cut = end + h.chunks[k + 1].bytes / 2;
    const DecodeResult d = decode_vw(std::string_view(bytes).substr(0, cut));
    EXPECT_TRUE(d.truncated);
    EXPECT_EQ(d.chunks_decoded, static_cast<int>(k + 1));
    // The error the file states is the error of what was decoded.
    EXPECT_NEAR(max_abs(v, d.volume), d.max_error, 1e-9);
    EXPECT_LE(d.rmse, previous * 1.0001);
    previous = d.rmse;
  }
  // Cut inside the header or inside chunk 0: refused.
  EXPECT_THROW(decode_vw(std::string_view(bytes).substr(0, h.header_bytes - 1)), Error);
  EXPECT_THROW(decode_vw(std::string_view(bytes).substr(0, h.header_bytes + h.chunks[0].bytes - 1)), Error);
}

TEST(WaveletCodec, DamagedBytesAreRefusedNotTrusted) {
  const Volume v = test_volume(ScalarType::u16);
  EncodeOptions o;
  o.bound = 2;
  std::string bytes = encode_vw(v, o);
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    std::string b = bytes;
    b[rng() % b.size()] ^= static_cast<char>(1 + rng() % 255);
    try {
      (void)decode_vw(b);
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input);
    }
  }
}

TEST(WaveletCodec, RegionOfInterestGetsItsOwnBound) {
  const Volume v = test_volume(ScalarType::f32, 30, 30, 12);
  EncodeOptions o;
  o.bound = 20;
  o.roi_bound = 0.5;
  o.roi_mask.assign(v.size(), 0);
  for (std::size_t z = 3; z < 8; ++z)
    for (std::size_t y = 10; y < 20; ++y)
      for (std::size_t x = 10; x < 20; ++x) o.roi_mask[v.index(x, y, z)] = 1;
  const DecodeResult d = decode_vw(encode_vw(v, o));
  double inside = 0, outside = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double e = std::fabs(v.voxels[i] - d.volume.voxels[i]);
    (o.roi_mask[i] ? inside : outside) = std::max(o.roi_mask[i] ? inside : outside, e);
  }
  EXPECT_LE(inside, 0.5);
  EXPECT_LE(outside, 20);
  EXPECT_GT(outside, 1);
}

TEST(WaveletCodec, RmseTargetIsMet) {
  const Volume v = test_volume(ScalarType::f32, 32, 32, 16);
  for (Wavelet w : {Wavelet::cdf97, Wavelet::cdf53}) {
    EncodeOptions o;
    o.mode = Mode::rmse;
    o.bound = 2.0;
    o.wavelet = w;
    EncodeStats st;
    const DecodeResult d = decode_vw(encode_vw(v, o, &st));
    double s = 0;
    for (std::size_t i = 0; i < v.size(); ++i) s += std::pow(v.voxels[i] - d.volume.voxels[i], 2);
    const double rmse = std::sqrt(s / static_cast<double>(v.size()));
    EXPECT_LE(rmse, 2.0) << wavelet_name(w);
    EXPECT_GT(rmse, 1.0) << wavelet_name(w);  // the search uses the budget
  }
}

TEST(WaveletCodec, SameBytesForAnyThreadCount) {
  const Volume v = test_volume(ScalarType::f32, 40, 40, 40);
  EncodeOptions o;
  o.bound = 1;
  o.threads = 1;
  const std::string a = encode_vw(v, o);
  o.threads = 4;
  EXPECT_EQ(a, encode_vw(v, o));
}

TEST(WaveletCodec, SameVolumeForAnyDecodeThreadCount) {
  // Slabs and transform blocks are spread over threads; the voxels must not depend on
  // how. Integer data (cdf53, 5/3 lossless) and an RMS-coded cdf97 float volume.
  const Volume v = test_volume(ScalarType::i16, 37, 29, 41, 20.0);
  const Volume f = test_volume(ScalarType::f32, 30, 21, 35);
  EncodeOptions a, b, c;
  a.bound = 3;
  b.mode = Mode::lossless;
  c.mode = Mode::rmse;
  c.bound = 1.0;
  c.wavelet = Wavelet::cdf97;
  for (const std::string& bytes : {encode_vw(v, a), encode_vw(v, b), encode_vw(f, c)}) {
    const std::vector<double> one = decode_vw(bytes, 1).volume.voxels;
    for (int threads : {2, 3, 7}) {
      const std::vector<double> many = decode_vw(bytes, threads).volume.voxels;
      ASSERT_EQ(one.size(), many.size());
      EXPECT_EQ(0, std::memcmp(one.data(), many.data(), one.size() * sizeof(double))) << "threads " << threads;
    }
  }
}

TEST(WaveletCodec, StoredAsRoundsLikeStdRound) {
  // The dequantiser rounds without libm; it must agree with std::round (halves away
  // from zero, the sign of a zero kept) and clamp to the type.
  const double values[] = {0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.3, -0.0, 0.0, 3.0000000000000004,
                           32767.5, -32768.5, 40000.2, -1e300, 1e300, 4503599627370495.5, 9.1e15, -123.50000000001};
  for (double v : values) {
    const double want = std::clamp(std::round(v), -32768.0, 32767.0);
    const double got = stored_as(v, ScalarType::i16);
    EXPECT_EQ(0, std::memcmp(&want, &got, sizeof got)) << v << " -> " << got << " not " << want;
    const double want8 = std::clamp(std::round(v), 0.0, 255.0);
    const double got8 = stored_as(v, ScalarType::u8);
    EXPECT_EQ(0, std::memcmp(&want8, &got8, sizeof got8)) << v;
  }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-40000.0, 40000.0);
  for (int i = 0; i < 100000; ++i) {
    const double v = i % 2 ? u(rng) : std::floor(u(rng)) + 0.5;
    ASSERT_EQ(std::clamp(std::round(v), -32768.0, 32767.0), stored_as(v, ScalarType::i16)) << v;
  }
}

TEST(WaveletCodec, DequantiserAvx2MatchesScalar) {
  // Integer data with an integral step and offset: every value is offset + step * key
  // clamped to the type, computed in that order (what the scalar loop does and what the
  // AVX2 loop, taken on this machine when it has AVX2, must give bit for bit). Keys reach
  // past +-2^51, where the AVX2 conversion does not hold and its lanes go the scalar way;
  // lengths leave tails of 0-3 keys; in place and not.
  std::mt19937_64 rng(11);
  for (ScalarType type : {ScalarType::u8, ScalarType::i16, ScalarType::u16, ScalarType::i32})
    for (double step : {1.0, 2.0, 7.0, 1e6})
      for (double offset : {0.0, -0.0, -3.0, 129.0, -40000.0})
        for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{4}, std::size_t{37}}) {
          Quantiser q;
          q.step = step;
          q.offset = offset;
          std::vector<std::int64_t> keys(n);
          for (std::size_t i = 0; i < n; ++i)
            keys[i] = i % 5 == 4 ? kSpecialKeys[rng() % std::size(kSpecialKeys)]
                                 : static_cast<std::int64_t>(rng() % 200001) - 100000;
          const auto [got, in_place] = dequantise_both_ways(keys, q, type);
          ASSERT_EQ(got.size(), n);
          const double lo = stored_as(-1e300, type), hi = stored_as(1e300, type);
          for (std::size_t i = 0; i < n; ++i) {
            const double want = std::min(hi, std::max(lo, offset + step * static_cast<double>(keys[i])));
            ASSERT_EQ(0, std::memcmp(&want, &got[i], 8)) << "key " << keys[i] << " step " << step << " offset " << offset;
            ASSERT_EQ(0, std::memcmp(&want, &in_place[i], 8)) << "in place, key " << keys[i];
          }
        }
}

TEST(WaveletCodec, DequantiserAvx2MatchesScalarFloat32) {
  // Float32 data: every value is stored_as(offset + step * key, f32), the definition the
  // AVX2 loop (taken on this machine when it has AVX2) must give bit for bit: values
  // that round to float differently from double, that overflow float to +-infinity or
  // lie just below the overflow threshold, zeros, keys past +-2^51 (the scalar way), and
  // tails of 0-3 keys, in place and not.
  std::mt19937_64 rng(13);
  const double fmax = static_cast<double>(std::numeric_limits<float>::max());
  for (double step : {2e-3, 0.1, 1.0 / 3.0, 1e20, fmax / 1000.0, fmax * (1 + 0.5e-7) / 1000.0})
    for (double offset : {0.0, -0.0, 0.37, -1e5, fmax})
      for (std::size_t n : {std::size_t{0}, std::size_t{3}, std::size_t{4}, std::size_t{41}}) {
        Quantiser q;
        q.step = step;
        q.offset = offset;
        std::vector<std::int64_t> keys(n);
        for (std::size_t i = 0; i < n; ++i)
          keys[i] = i % 5 == 4 ? kSpecialKeys[rng() % std::size(kSpecialKeys)]
                  : i % 5 == 3 ? static_cast<std::int64_t>(rng() % 2001) - 1000 + (rng() % 2 ? 1000 : -1000)
                               : static_cast<std::int64_t>(rng() % 200001) - 100000;
        const auto [got, in_place] = dequantise_both_ways(keys, q, ScalarType::f32);
        ASSERT_EQ(got.size(), n);
        for (std::size_t i = 0; i < n; ++i) {
          const double want = stored_as(key_value(q, keys[i]), ScalarType::f32);
          ASSERT_EQ(0, std::memcmp(&want, &got[i], 8)) << "key " << keys[i] << " step " << step << " offset " << offset;
          ASSERT_EQ(0, std::memcmp(&want, &in_place[i], 8)) << "in place, key " << keys[i];
        }
      }
}

TEST(WaveletCodec, ResealedMutationsFailCleanly) {
  // What tests/fuzz/fuzz_vw.cpp does, for a fixed budget in the suite: mutations with
  // valid hashes reach the parsers and the range decoder; only fest::Error may come out.
  const Volume v = test_volume(ScalarType::f32, 12, 10, 9);
  EncodeOptions o;
  o.bound = 0.5;
  o.roi_mask.assign(v.size(), 0);
  o.roi_mask[5] = 1;
  o.roi_bound = 0.1;
  const std::string bytes = encode_vw(v, o);
  std::mt19937_64 rng(17);
  int decoded = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string b = bytes;
    const int flips = 1 + static_cast<int>(rng() % 3);
    for (int f = 0; f < flips; ++f) b[rng() % b.size()] ^= static_cast<char>(1u << (rng() % 8));
    if (rng() % 4 == 0) b.resize(rng() % b.size());
    reseal_vw(b, 1 << 16);
    try {
      const DecodeResult d = decode_vw(b, 1, -1, 1 << 16);
      EXPECT_EQ(d.volume.voxels.size(), d.volume.size());
      ++decoded;
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input) << e.what();
    }
  }
  EXPECT_GT(decoded, 0);
}

// Version 5 leaves out geometry at its default (unit spacing, zero origin, identity
// direction) and stores anything else exactly, -0.0 and a rotated direction included;
// the header shrinks by the doubles left out.
TEST(WaveletCodec, HeaderGeometryDefaultsAndStoredValuesRoundTrip) {
  Volume v = test_volume(ScalarType::f32);
  EncodeOptions o;
  o.bound = 1.0;
  auto header_bytes = [](const std::string& bytes) { return read_vw_header(bytes).header_bytes; };
  v.spacing = {1, 1, 1};
  v.origin = {0, 0, 0};
  v.direction = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::string plain = encode_vw(v, o);
  const DecodeResult d0 = decode_vw(plain, 1);
  EXPECT_EQ(d0.volume.spacing, v.spacing);
  EXPECT_EQ(d0.volume.origin, v.origin);
  EXPECT_EQ(d0.volume.direction, v.direction);
  const std::vector<std::pair<std::string, std::function<void(Volume&)>>> changes = {
      {"spacing", [](Volume& x) { x.spacing = {0.5, 0.7, 1.2}; }},
      {"origin", [](Volume& x) { x.origin = {-3, 4, 5}; }},
      {"origin -0", [](Volume& x) { x.origin = {-0.0, 0, 0}; }},
      {"direction", [](Volume& x) { x.direction = {0, 1, 0, -1, 0, 0, 0, 0, 1}; }}};
  for (const auto& [name, change] : changes) {
    Volume w = v;
    change(w);
    const std::string bytes = encode_vw(w, o);
    const DecodeResult d = decode_vw(bytes, 1);
    EXPECT_EQ(0, std::memcmp(d.volume.spacing.data(), w.spacing.data(), sizeof w.spacing)) << name;
    EXPECT_EQ(0, std::memcmp(d.volume.origin.data(), w.origin.data(), sizeof w.origin)) << name;
    EXPECT_EQ(0, std::memcmp(d.volume.direction.data(), w.direction.data(), sizeof w.direction)) << name;
    const std::size_t stored = name == "direction" ? 72 : 24;
    EXPECT_EQ(header_bytes(bytes), header_bytes(plain) + stored) << name;
  }
}

// Without a stated level count, a volume that is zero on most of its rows (a plume in
// empty space) is also coded with one level and the smaller file kept; a dense volume
// keeps the default depth. Either way the bound holds.
TEST(WaveletCodec, SparseVolumesMayTakeOneLevel) {
  Volume sparse;
  sparse.resize(48, 40, 36);
  sparse.type = ScalarType::f32;
  std::mt19937_64 rng(8);
  std::normal_distribution<double> g(0.0, 0.05);
  for (std::size_t z = 0; z < 36; ++z)
    for (std::size_t y = 0; y < 40; ++y)
      for (std::size_t x = 0; x < 48; ++x) {
        const double r2 = std::pow(x - 20.0, 2) + std::pow(y - 18.0, 2) + std::pow(z - 10.0, 2);
        if (r2 < 64) sparse.at(x, y, z) = static_cast<float>(std::exp(-r2 / 30.0) + g(rng));  // a blob; zero around
      }
  const Volume dense = test_volume(ScalarType::f32, 48, 40, 36);
  for (double bound : {1e-3, 1e-2}) {
    EncodeOptions o;
    o.bound = bound;
    const std::string chosen = encode_vw(sparse, o);
    EncodeOptions deep = o;
    deep.levels = default_levels(sparse.dims);
    const std::string by_default = encode_vw(sparse, deep);
    EXPECT_EQ(read_vw_header(chosen).levels, 1) << bound;
    EXPECT_LE(chosen.size(), by_default.size()) << bound;
    EXPECT_LE(max_abs(sparse, decode_vw(chosen, 1).volume), bound);
    EXPECT_EQ(read_vw_header(encode_vw(dense, o)).levels, default_levels(dense.dims)) << bound;
  }
}
