// Packed slabs of .vw format versions 4 and 5 (lib/wavelet/packed_coder.hpp, docs/volwave.md §4
// "Packed slabs"): groups of every width round-trip through the scalar and the AVX2
// unpacker alike, packed slabs decode to their coefficients, damage is refused, and a
// whole file decodes to the same voxels whichever slabs the encoder packed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "core/error.hpp"
#include "wavelet/band_coder.hpp"
#include "wavelet/packed_coder.hpp"
#include "wavelet/vw_codec.hpp"

using namespace fest;
using namespace fest::wavelet;

namespace {

// A group of n values of width exactly k (k = 0: zeros), `density` the share non-zero.
std::vector<std::int64_t> make_group(std::mt19937_64& rng, int n, int k, double density) {
  std::vector<std::int64_t> v(static_cast<std::size_t>(n), 0);
  if (k == 0) return v;
  std::uniform_real_distribution<double> u(0, 1);
  const std::uint64_t top = std::uint64_t{1} << (k - 1);
  for (auto& x : v) {
    if (u(rng) >= density) continue;
    const std::uint64_t m = (rng() & (top - 1 + top)) | 1;  // < 2^k
    x = static_cast<std::int64_t>(m & (top | (top - 1)));
    if (rng() & 1) x = -x;
  }
  // One value carries the top bit, so the width is k.
  const std::size_t at = static_cast<std::size_t>(rng() % static_cast<std::uint64_t>(n));
  const std::int64_t m = static_cast<std::int64_t>(top | (rng() & (top - 1)));
  v[at] = rng() & 1 ? -m : m;
  return v;
}

}  // namespace

TEST(WaveletPacked, GroupsOfEveryWidthRoundTripScalarAndAvx2Alike) {
  std::mt19937_64 rng(17);
  for (bool masked : {false, true})
    for (double density : {0.05, 0.3, 1.0}) {
      std::vector<std::vector<std::int64_t>> groups;
      std::vector<int> widths;
      BitWriter w;
      for (int rep = 0; rep < 4; ++rep)
        for (int k = 0; k <= 63; ++k)
          for (int n : {kPackGroup, 1, 5}) {
            groups.push_back(make_group(rng, n, k, density));
            ASSERT_EQ(pack_width(groups.back().data(), n), k);
            widths.push_back(k);
            pack_group(w, groups.back().data(), n, k, masked);
          }
      std::string bytes = w.finish();
      const std::size_t size = bytes.size();
      bytes.append(kPackSlack, '\0');
      const auto* base = reinterpret_cast<const std::uint8_t*>(bytes.data());
      std::uint64_t bs = 0, bv = 0;
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const int k = widths[g], n = static_cast<int>(groups[g].size());
        if (k == 0) continue;
        std::int64_t a[kPackGroup] = {}, b[kPackGroup] = {};
        const int mask = pack_mask(groups[g].data(), n);
        const bool avx2 = packed_avx2_available();
        if (n == kPackGroup && masked) {
          bs = unpack_group_scalar(base, bs, k, mask, a);
          bv = avx2 ? unpack_group_avx2(base, bv, k, mask, b) : unpack_group_scalar(base, bv, k, mask, b);
        } else if (n == kPackGroup) {
          bs = unpack_dense_scalar(base, bs, k, a);
          bv = avx2 ? unpack_dense_avx2(base, bv, k, b) : unpack_dense_scalar(base, bv, k, b);
        } else if (masked) {
          bs = unpack_partial(base, bs, k, mask, n, a);
          bv = unpack_partial(base, bv, k, mask, n, b);
        } else {
          bs = unpack_dense_partial(base, bs, k, n, a);
          bv = unpack_dense_partial(base, bv, k, n, b);
        }
        ASSERT_EQ(bs, bv) << "group " << g << " width " << k << " masked " << masked;
        for (int i = 0; i < n; ++i) {
          ASSERT_EQ(a[i], groups[g][static_cast<std::size_t>(i)]) << "group " << g << " width " << k << " value " << i;
          ASSERT_EQ(b[i], a[i]);
        }
      }
      EXPECT_EQ((bs + 7) / 8, size);
    }
  if (!packed_avx2_available()) GTEST_SKIP() << "no AVX2 here: the scalar unpacker alone was checked";
}

namespace {

// A pyramid whose detail bands hold sparse and dense regions and rows of zeros.
std::vector<std::int64_t> make_pyramid(const Dims& dims, std::uint64_t seed) {
  std::vector<std::int64_t> data(dims[0] * dims[1] * dims[2], 0);
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> ex(0.2);
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::size_t x = i % dims[0], y = (i / dims[0]) % dims[1];
    if (y % 7 == 3) continue;                          // zero rows
    if (x > 20 && (rng() % 16) != 0) continue;        // sparse part
    const auto m = static_cast<std::int64_t>(ex(rng)) << (x % 10 < 2 ? 20 : 0);  // wide groups in every band
    data[i] = rng() & 1 ? m : -m;
  }
  return data;
}

}  // namespace

TEST(WaveletPacked, SlabsRoundTripAndRefuseDamage) {
  const Dims dims{37, 30, 20};
  const auto bands = subbands(dims, 2);
  const std::vector<std::int64_t> data = make_pyramid(dims, 5);
  int packed = 0;
  for (const auto& band : bands) {
    const Subband* parent = parent_of(bands, band);
    for (const auto& slab : slabs_of(band)) {
      const std::string bytes = encode_slab(data.data(), dims, band, parent, slab, SlabCoding::packed);
      ASSERT_FALSE(bytes.empty());
      if (band.orientation == 0) {
        EXPECT_NE(bytes[0], 2) << "the approximation band is never packed";
        continue;
      }
      ASSERT_EQ(bytes[0], 2);
      ++packed;
      RowList rows_s, rows_v;
      std::vector<std::int64_t> out_s(data.size(), 0), out_v(data.size(), 0);
      decode_packed_slab(std::string_view(bytes).substr(1), out_s.data(), dims, band, slab, 40, rows_s, false);
      decode_slab(bytes, out_v.data(), dims, band, parent, slab, 40, &rows_v);
      EXPECT_EQ(rows_s, rows_v);
      std::size_t nonzero_rows = 0;
      for (std::size_t z = slab.z0; z < slab.z1; ++z)
        for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y) {
          bool nz = false;
          for (std::size_t x = band.lo[0]; x < band.hi[0]; ++x) {
            const std::size_t i = x + dims[0] * (y + dims[1] * z);
            ASSERT_EQ(out_s[i], data[i]) << band.level << " " << band.orientation << " " << x << "," << y << "," << z;
            ASSERT_EQ(out_v[i], data[i]);
            nz = nz || data[i] != 0;
          }
          nonzero_rows += nz;
        }
      EXPECT_EQ(rows_s.size(), nonzero_rows);
      // A version-3 file cannot hold a packed slab; cut or damaged streams are refused.
      std::vector<std::int64_t> junk(data.size(), 0);
      EXPECT_THROW(decode_slab(bytes, junk.data(), dims, band, parent, slab, 40, nullptr, false), Error);
      EXPECT_THROW(decode_slab(bytes.substr(0, bytes.size() - 1), junk.data(), dims, band, parent, slab, 40), Error);
      std::string longer = bytes + std::string(3, '\0');
      EXPECT_THROW(decode_slab(longer, junk.data(), dims, band, parent, slab, 40), Error);
      // Widths above the header's exponent bound are refused (the wide groups need 25 bits).
      EXPECT_THROW(decode_slab(bytes, junk.data(), dims, band, parent, slab, 10), Error);
    }
  }
  EXPECT_GT(packed, 10);
}

// Format version 5: a slab with few symbols per table may state a lower table precision
// (docs/volwave.md §4 "Table precision"). Every precision decodes to the coefficients,
// and a version-4 file cannot hold one.
TEST(WaveletPacked, ReducedTablePrecisionRoundTripsAndIsRefusedInVersion4) {
  const Dims dims{37, 30, 20};
  const auto bands = subbands(dims, 2);
  std::vector<std::int64_t> data(dims[0] * dims[1] * dims[2], 0);
  // Sparse: a few small values in a few rows, so each table holds a handful of symbols.
  std::mt19937_64 rng(9);
  for (std::size_t i = 0; i < data.size(); i += 1 + rng() % 97) data[i] = static_cast<std::int64_t>(rng() % 7) - 3;
  int reduced = 0;
  for (const auto& band : bands) {
    if (band.orientation == 0) continue;
    for (const auto& slab : slabs_of(band)) {
      for (double slack : {0.0, 0.5, 1e9}) {
        const std::string bytes = encode_packed_slab(data.data(), dims, band, slab, -1, slack);
        ASSERT_FALSE(bytes.empty());
        const int variant = static_cast<std::uint8_t>(bytes[0]);
        ASSERT_LT(variant, 6 * 7);  // 3 maps x masks x precisions 11..5
        RowList rows;
        std::vector<std::int64_t> out(data.size(), 0), out_s(data.size(), 0);
        decode_packed_slab(bytes, out.data(), dims, band, slab, 40, rows);
        decode_packed_slab(bytes, out_s.data(), dims, band, slab, 40, rows, false);
        for (std::size_t z = slab.z0; z < slab.z1; ++z)
          for (std::size_t y = band.lo[1]; y < band.hi[1]; ++y)
            for (std::size_t x = band.lo[0]; x < band.hi[0]; ++x) {
              const std::size_t i = x + dims[0] * (y + dims[1] * z);
              ASSERT_EQ(out[i], data[i]) << variant;
              ASSERT_EQ(out_s[i], data[i]) << variant;
            }
        std::vector<std::int64_t> junk(data.size(), 0);
        if (variant >= 6) {
          ++reduced;
          EXPECT_THROW(decode_packed_slab(bytes, junk.data(), dims, band, slab, 40, rows,
                                          packed_avx2_available(), false),
                       Error);
        } else {
          EXPECT_NO_THROW(decode_packed_slab(bytes, junk.data(), dims, band, slab, 40, rows,
                                             packed_avx2_available(), false));
        }
        // A precision no encoder writes (variant 42 and above) is refused.
        std::string beyond = bytes;
        beyond[0] = static_cast<char>(42 + variant % 6);
        EXPECT_THROW(decode_packed_slab(beyond, junk.data(), dims, band, slab, 40, rows), Error);
      }
    }
  }
  EXPECT_GT(reduced, 5);  // the sparse slabs do take lower precisions
}

TEST(WaveletPacked, FilesDecodeToTheSameVoxelsWhateverIsPacked) {
  // A smooth volume with noise and an empty corner, at an integer and a float bound: the
  // voxels are those of the coefficients, not of how they were coded.
  Volume v;
  v.dims = {40, 33, 27};
  v.type = ScalarType::f32;
  v.voxels.resize(v.dims[0] * v.dims[1] * v.dims[2]);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0, 0.05);
  for (std::size_t i = 0; i < v.voxels.size(); ++i) {
    const double x = static_cast<double>(i % v.dims[0]), y = static_cast<double>((i / v.dims[0]) % v.dims[1]);
    v.voxels[i] = x < 12 ? 0.0 : std::sin(0.2 * x) * std::cos(0.3 * y) + noise(rng);
  }
  for (double bound : {1e-3, 0.1}) {
    std::vector<std::vector<double>> decoded;
    std::vector<std::size_t> sizes;
    for (double slack : {-1.0, 0.0, kPackedSlackSpeed, 1e9}) {
      EncodeOptions o;
      o.mode = Mode::max_error;
      o.bound = bound;
      o.packed_slack = slack;
      const std::string vw = encode_vw(v, o);
      EXPECT_EQ(static_cast<unsigned char>(vw[7]), kVwFormatVersion);
      const DecodeResult d = decode_vw(vw, 1);
      double worst = 0;
      for (std::size_t i = 0; i < v.voxels.size(); ++i)
        worst = std::max(worst, std::fabs(d.volume.voxels[i] - static_cast<double>(static_cast<float>(v.voxels[i]))));
      EXPECT_LE(worst, bound);
      decoded.push_back(d.volume.voxels);
      sizes.push_back(vw.size());
      // Truncated after the approximation: still decodes (docs/volwave.md §5).
      const VwHeader h = read_vw_header(vw);
      const DecodeResult c = decode_vw(std::string_view(vw).substr(0, h.header_bytes + h.chunks[0].bytes + h.chunks[1].bytes), 1);
      EXPECT_TRUE(c.truncated);
      EXPECT_EQ(c.chunks_decoded, 2);
    }
    for (std::size_t k = 1; k < decoded.size(); ++k)
      EXPECT_EQ(std::memcmp(decoded[k].data(), decoded[0].data(), decoded[0].size() * sizeof(double)), 0);
    // Slack 0 packs only where packing is not larger: never larger than no packing.
    EXPECT_LE(sizes[1], sizes[0]);
    EXPECT_LE(sizes[2], sizes[0] * 13 / 10 + 64);
  }
}
