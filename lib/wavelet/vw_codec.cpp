#include "wavelet/vw_codec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "core/crc32.hpp"
#include "core/error.hpp"
#include "core/little_endian.hpp"
#include "core/error_stats.hpp"
#include "core/parallel_for.hpp"
#include "wavelet/band_coder.hpp"
#include "wavelet/rans.hpp"

namespace fest::wavelet {

const char* mode_name(Mode m) noexcept {
  switch (m) {
    case Mode::lossless: return "lossless";
    case Mode::max_error: return "max-error";
    case Mode::rmse: return "rmse";
  }
  return "?";
}

std::uint64_t VwHeader::total_bytes() const noexcept {
  std::uint64_t t = header_bytes;
  for (const auto& c : chunks) t += c.bytes;
  return t;
}

namespace {

constexpr char kMagic[7] = {'\x89', 'V', 'W', '\r', '\n', '\x1a', '\n'};  // then the version byte
constexpr int kMaxLevels = 16;

// The checksum of the header and of every chunk (fest-vw(5)): 64-bit FNV-1a up to
// version 4; from version 5 zlib's CRC-32, which reads 6.7 bytes a ns against FNV-1a's
// one (FNV-1a's chain of multiplies was 17 us of the 66^3 plume's 420 us decode, and is
// 5 ms for a 5 MB file).
std::uint64_t checksum(std::string_view s, int version) noexcept {
  if (version >= 5) return crc32_of(s);
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

int bit_width(std::uint64_t v) noexcept { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

// ---- little-endian bytes (core/little_endian.hpp) ----
struct Writer {
  std::string out;
  void u8(std::uint8_t v) { little_endian::put_u8(out, v); }
  void u32(std::uint32_t v) { little_endian::put_u32(out, v); }
  void u64(std::uint64_t v) { little_endian::put_u64(out, v); }
  void f64(double v) { little_endian::put_f64(out, v); }
  void varint(std::uint64_t v) { little_endian::put_varint(out, v); }
};

// What running out of a part of the file means (little_endian::Reader): `what` names it.
struct PartErrors {
  PartErrors(const char* part) : what(part) {}  // NOLINT: a Reader is made from its part's name
  [[noreturn]] void truncated(std::size_t n, std::size_t pos) const {
    throw bad_input("truncated {}: needs {} more bytes at byte {}", what, n, pos);
  }
  [[noreturn]] void varint_too_long(std::size_t pos) const {
    throw bad_input("{}: a variable-length number runs past 64 bits at byte {}", what, pos);
  }
  const char* what;
};
using Reader = little_endian::Reader<PartErrors>;

// ---- the region of interest as runs (alternating outside/inside, starting outside) ----
void write_runs(Writer& w, const std::vector<std::uint8_t>& mask) {
  std::vector<std::uint64_t> runs;
  std::uint8_t cur = 0;
  std::uint64_t len = 0;
  for (std::uint8_t m : mask) {
    const std::uint8_t b = m ? 1 : 0;
    if (b != cur) {
      runs.push_back(len);
      cur = b;
      len = 0;
    }
    ++len;
  }
  runs.push_back(len);
  w.varint(runs.size());
  for (auto r : runs) w.varint(r);
}

std::vector<std::uint8_t> read_runs(Reader& r, std::size_t voxels) {
  const std::uint64_t count = r.varint();
  if (count == 0 || count > voxels + 1) throw bad_input(".vw region of interest: {} runs for {} voxels", count, voxels);
  std::vector<std::uint8_t> mask;
  mask.reserve(voxels);
  std::uint8_t cur = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint64_t len = r.varint();
    if (len > voxels - mask.size()) throw bad_input(".vw region of interest: runs exceed the {} voxels", voxels);
    mask.insert(mask.end(), len, cur);
    cur ^= 1;
  }
  if (mask.size() != voxels) throw bad_input(".vw region of interest: runs cover {} of {} voxels", mask.size(), voxels);
  return mask;
}

// ---- reconstruction shared by the encoder's table and the decoder ----

double step_at(const VwHeader& h, const std::vector<std::uint8_t>& roi, std::size_t i) noexcept {
  return (!roi.empty() && roi[i]) ? h.roi_step : h.quantiser.step;
}

// The decoder keeps one buffer of n doubles: it first holds the int64 coefficients
// (their bytes; a zero double and a zero int64 are the same bytes, so the zeroed
// buffer already stands for the missing detail bands), then, transformed back and
// dequantised in place, the voxel values. One buffer instead of two halves what a
// decode allocates and touches. The library is compiled with -fno-strict-aliasing
// (lib/wavelet/CMakeLists.txt), which makes the int64 view of the double storage defined
// for GCC and Clang; the keys are read back through memcpy and every element is
// rewritten as a double before any double is read.
// Reserves room for n doubles and, on Linux, asks for transparent huge pages for it
// before anything touches it: a decode writes every voxel once, and 4 KiB pages would
// cost a page fault per 512 voxels (an eighth of the decode time on the CT head).
void reserve_large(std::vector<double>& buffer, std::size_t n) {
  buffer.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t{1} << 21;
  const auto begin = (reinterpret_cast<std::uintptr_t>(buffer.data()) + huge - 1) & ~(huge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(buffer.data() + n)) & ~(huge - 1);
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

std::int64_t* coefficients_in(std::vector<double>& buffer) noexcept {
  return reinterpret_cast<std::int64_t*>(buffer.data());
}

// Coefficients (in `buffer`, as above) -> voxel values in the stored type, in place.
// `nonzero_rows` (integer wavelets): the rows holding non-zero coefficients per level,
// as inverse_3d takes them (null: anywhere).
void reconstruct_in_place(const VwHeader& h, std::vector<double>& buffer, const std::vector<std::uint8_t>& roi,
                          int threads, const std::vector<RowList>* nonzero_rows = nullptr) {
  const std::size_t n = buffer.size();
  std::int64_t* coef = coefficients_in(buffer);
  if (h.wavelet == Wavelet::cdf97) {
    for (std::size_t i = 0; i < n; ++i) {
      std::int64_t k;
      std::memcpy(&k, &buffer[i], 8);
      buffer[i] = static_cast<double>(k) * h.quantiser.step;
    }
    inverse_3d(buffer, h.dims, h.levels, threads);
    for (auto& v : buffer) v = stored_as(v + h.quantiser.offset, h.type);
    return;
  }
  if (nonzero_rows && roi.empty()) {
    // The parts of rows known to be zero after the transform are not even read by the
    // dequantiser.
    std::vector<RowSpan> row_spans;
    inverse_3d(coef, h.dims, h.levels, h.wavelet, threads, *nonzero_rows, &row_spans);
    dequantise_rows_in_place(buffer.data(), h.dims[0], row_spans, h.quantiser, h.type, threads);
    return;
  }
  if (nonzero_rows) inverse_3d(coef, h.dims, h.levels, h.wavelet, threads, *nonzero_rows);
  else inverse_3d(coef, h.dims, h.levels, h.wavelet, threads);
  if (roi.empty()) {
    dequantise_in_place(buffer.data(), n, h.quantiser, h.type, threads);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      std::int64_t k;
      std::memcpy(&k, &buffer[i], 8);
      buffer[i] = stored_as(h.quantiser.offset + step_at(h, roi, i) * static_cast<double>(k), h.type);
    }
  }
}

// Coefficients -> voxel values (the encoder's error table).
std::vector<double> reconstruct(const VwHeader& h, const std::vector<std::int64_t>& coef,
                                const std::vector<std::uint8_t>& roi, int threads) {
  std::vector<double> buffer(coef.size());
  std::memcpy(buffer.data(), coef.data(), coef.size() * sizeof(std::int64_t));
  reconstruct_in_place(h, buffer, roi, threads);
  return buffer;
}

struct Errors {
  double max_error = 0, rmse = 0, roi_max_error = 0;
};

Errors measure(const std::vector<double>& a, const std::vector<double>& b, const std::vector<std::uint8_t>& roi) {
  Errors e;
  // Sums per block of 2^16 voxels, added in block order: the rounding of the total stays
  // that of the .vw files written so far.
  const std::size_t block = 1 << 16, n = a.size();
  const std::size_t blocks = (n + block - 1) / block;
  ErrorAccumulator total;
  for (std::size_t k = 0; k < blocks; ++k) {
    ErrorAccumulator acc;
    for (std::size_t i = k * block; i < std::min(n, (k + 1) * block); ++i) {
      if (std::isnan(a[i]) && std::isnan(b[i])) {
        acc.add(0);  // both missing: no error, but a voxel of the mean
        continue;
      }
      const double d = std::isnan(a[i]) != std::isnan(b[i]) ? std::numeric_limits<double>::infinity() : std::fabs(a[i] - b[i]);
      acc.add(d);
      if (!roi.empty() && roi[i]) e.roi_max_error = std::max(e.roi_max_error, d);
    }
    total.merge(acc);
  }
  e.max_error = total.max_abs;
  e.rmse = total.rmse();
  return e;
}

// Every (band, slab) stream of a chunk, in file order.
struct Stream {
  const Subband* band;
  const Subband* parent;
  Slab slab;
};

std::vector<std::vector<Stream>> streams_by_chunk(const std::vector<Subband>& bands, int levels) {
  std::vector<std::vector<Stream>> out(static_cast<std::size_t>(levels) + 1);
  for (const auto& b : bands)
    for (const auto& s : slabs_of(b)) out[static_cast<std::size_t>(chunk_of(b, levels))].push_back({&b, parent_of(bands, b), s});
  return out;
}

// The geometry a version-5 header leaves out when it has its default value (bits of the
// byte that versions 3 and 4 keep reserved and zero): with the varints and 4-byte CRCs
// below, a 66^3 plume's header went from 404 bytes to 202 (docs/volwave.md §4).
constexpr std::uint8_t kHasSpacing = 1, kHasOrigin = 2, kHasDirection = 4;
constexpr std::array<double, 3> kUnitSpacing{1, 1, 1}, kZeroOrigin{0, 0, 0};
constexpr std::array<double, 9> kIdentity{1, 0, 0, 0, 1, 0, 0, 0, 1};

template <std::size_t N>
bool same_bits(const std::array<double, N>& a, const std::array<double, N>& b) noexcept {
  return std::memcmp(a.data(), b.data(), sizeof a) == 0;  // -0.0 is stored, not defaulted
}

// A coefficient chunk's streams: their lengths (uint32 up to version 4, varints from
// version 5), then their bytes, which must fill the chunk exactly.
std::vector<std::string_view> split_chunk(std::string_view chunk, std::size_t count, int version, int k) {
  Reader r(chunk, ".vw chunk");
  std::vector<std::uint64_t> lengths(count);
  if (version < 5 && chunk.size() < 4 * count)
    throw bad_input(".vw chunk {}: {} bytes cannot list {} streams", k, chunk.size(), count);
  for (auto& len : lengths) len = version >= 5 ? r.varint() : r.u32();
  std::size_t at = r.pos();
  std::vector<std::string_view> parts(count);
  for (std::size_t s = 0; s < count; ++s) {
    if (lengths[s] > chunk.size() - at) throw bad_input(".vw chunk {}: stream {} runs past the chunk", k, s);
    parts[s] = chunk.substr(at, static_cast<std::size_t>(lengths[s]));
    at += static_cast<std::size_t>(lengths[s]);
  }
  if (at != chunk.size()) throw bad_input(".vw chunk {}: {} unused bytes", k, chunk.size() - at);
  return parts;
}

std::string write_header(const VwHeader& h, const std::vector<std::uint8_t>& roi) {
  const bool compact = h.version >= 5;
  Writer w;
  w.out.append(kMagic, 7);
  w.u8(static_cast<std::uint8_t>(h.version));
  w.u8(static_cast<std::uint8_t>(h.mode));
  w.u8(static_cast<std::uint8_t>(h.wavelet));
  w.u8(static_cast<std::uint8_t>(h.levels));
  w.u8(static_cast<std::uint8_t>(h.type));
  w.u8(static_cast<std::uint8_t>(h.quantiser.kind));
  w.u8(static_cast<std::uint8_t>(h.max_exponent));
  w.u8(roi.empty() ? 0 : 1);
  const std::uint8_t geometry = !compact ? 0
                                         : static_cast<std::uint8_t>((same_bits(h.spacing, kUnitSpacing) ? 0 : kHasSpacing) |
                                                                     (same_bits(h.origin, kZeroOrigin) ? 0 : kHasOrigin) |
                                                                     (same_bits(h.direction, kIdentity) ? 0 : kHasDirection));
  w.u8(geometry);
  for (auto d : h.dims) compact ? w.varint(d) : w.u64(d);
  if (!compact || (geometry & kHasSpacing))
    for (double v : h.spacing) w.f64(v);
  if (!compact || (geometry & kHasOrigin))
    for (double v : h.origin) w.f64(v);
  if (!compact || (geometry & kHasDirection))
    for (double v : h.direction) w.f64(v);
  w.f64(h.quantiser.step);
  w.f64(h.quantiser.offset);
  w.f64(h.bound);
  if (!compact || !roi.empty()) {
    w.f64(h.roi_step);
    w.f64(h.roi_bound);
  }
  compact ? w.varint(h.chunks.size()) : w.u32(static_cast<std::uint32_t>(h.chunks.size()));
  for (const auto& c : h.chunks) {
    if (compact) {
      w.varint(c.bytes);
      w.u32(static_cast<std::uint32_t>(c.hash));
    } else {
      w.u64(c.bytes);
      w.u64(c.hash);
    }
    w.f64(c.max_error);
    w.f64(c.rmse);
  }
  if (!roi.empty()) write_runs(w, roi);
  const std::uint64_t sum = checksum(w.out, h.version);
  compact ? w.u32(static_cast<std::uint32_t>(sum)) : w.u64(sum);
  return w.out;
}

VwHeader parse_header(std::string_view bytes, std::uint64_t max_voxels, std::vector<std::uint8_t>* roi,
                      bool check_hash = true) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 7) != 0) {
    if (bytes.size() >= 3 && bytes.substr(1, 2) == "VW") throw bad_input("not a .vw file of version 3 to 5 (versions 1 and 2 are no longer read)");
    throw bad_input("not a .vw file (no \\x89VW magic)");
  }
  const int version = static_cast<std::uint8_t>(bytes[7]);
  if (version < kVwOldestReadVersion || version > kVwFormatVersion)
    throw bad_input("not a .vw file of version 3 to 5 (version {}{})", version,
                    version < kVwOldestReadVersion ? ": versions 1 and 2 are no longer read" : ": newer than this volwave");
  Reader r(bytes, ".vw header", 8);
  VwHeader h;
  h.version = version;
  const int mode = r.u8(), wavelet = r.u8(), levels = r.u8(), type = r.u8(), kind = r.u8();
  h.max_exponent = r.u8();
  const int has_roi = r.u8();
  const bool compact = version >= 5;
  const int geometry = r.u8();  // reserved (ignored) before version 5
  if (compact && geometry > 7) throw bad_input(".vw header: bad geometry flags {}", geometry);
  if (mode > 2) throw bad_input(".vw header: unknown mode {}", mode);
  if (wavelet > 2) throw bad_input(".vw header: unknown wavelet {}", wavelet);
  if (levels > kMaxLevels) throw bad_input(".vw header: {} levels (at most {})", levels, kMaxLevels);
  if (type > static_cast<int>(ScalarType::f64)) throw bad_input(".vw header: unknown value type {}", type);
  if (kind > 1) throw bad_input(".vw header: unknown key kind {}", kind);
  if (h.max_exponent > 60) throw bad_input(".vw header: coefficient exponent {} too large", h.max_exponent);
  if (has_roi > 1) throw bad_input(".vw header: bad region flag {}", has_roi);
  h.mode = static_cast<Mode>(mode);
  h.wavelet = static_cast<Wavelet>(wavelet);
  h.levels = levels;
  h.type = static_cast<ScalarType>(type);
  h.quantiser.kind = static_cast<KeyKind>(kind);
  std::uint64_t voxels = 1;
  for (auto& d : h.dims) {
    const std::uint64_t v = compact ? r.varint() : r.u64();
    if (v == 0 || v > max_voxels) throw bad_input(".vw header: dimension {} out of range", v);
    d = static_cast<std::size_t>(v);
    voxels *= v;
    if (voxels > max_voxels) throw bad_input(".vw header: more than {} voxels", max_voxels);
  }
  h.spacing = kUnitSpacing;
  h.origin = kZeroOrigin;
  h.direction = kIdentity;
  if (!compact || (geometry & kHasSpacing))
    for (double& v : h.spacing) v = r.f64();
  if (!compact || (geometry & kHasOrigin))
    for (double& v : h.origin) v = r.f64();
  if (!compact || (geometry & kHasDirection))
    for (double& v : h.direction) v = r.f64();
  h.quantiser.step = r.f64();
  h.quantiser.offset = r.f64();
  h.bound = r.f64();
  if (!compact || has_roi) {
    h.roi_step = r.f64();
    h.roi_bound = r.f64();
  }
  if (!(h.quantiser.step > 0) || !std::isfinite(h.quantiser.step) || !std::isfinite(h.quantiser.offset))
    throw bad_input(".vw header: bad quantiser step {} / offset {}", h.quantiser.step, h.quantiser.offset);
  if (has_roi && (!(h.roi_step > 0) || !std::isfinite(h.roi_step)))
    throw bad_input(".vw header: bad region step {}", h.roi_step);
  if (h.wavelet == Wavelet::cdf97 && h.quantiser.kind != KeyKind::scaled)
    throw bad_input(".vw header: cdf97 with float bit keys");
  const std::uint64_t nchunks = compact ? r.varint() : r.u32();
  if (nchunks != static_cast<std::uint64_t>(levels) + 2)
    throw bad_input(".vw header: {} chunks for {} levels (expected {})", nchunks, levels, levels + 2);
  std::uint64_t declared = 0;
  for (std::uint64_t i = 0; i < nchunks; ++i) {
    ChunkInfo c;
    c.bytes = compact ? r.varint() : r.u64();
    c.hash = compact ? r.u32() : r.u64();
    c.max_error = r.f64();
    c.rmse = r.f64();
    if (c.bytes > (1ull << 48)) throw bad_input(".vw header: chunk {} claims {} bytes", i, c.bytes);
    declared += c.bytes;
    h.chunks.push_back(c);
  }
  // A coded coefficient costs at least ~0.022 bit (the coder's most skewed
  // probability), so a file cannot describe more than ~400 voxels per byte.
  if (voxels > 400 * declared + (1u << 16))
    throw bad_input(".vw header: {} voxels cannot be coded in {} bytes", voxels, declared);
  std::vector<std::uint8_t> mask;
  if (has_roi) mask = read_runs(r, static_cast<std::size_t>(voxels));
  const std::size_t end = r.pos();
  const std::uint64_t hash = compact ? r.u32() : r.u64();
  if (check_hash && hash != checksum(bytes.substr(0, end), h.version)) throw bad_input(".vw header: checksum mismatch (damaged header)");
  h.header_bytes = r.pos();
  if (roi) *roi = std::move(mask);
  return h;
}

}  // namespace

VwHeader read_vw_header(std::string_view bytes, std::uint64_t max_voxels) {
  return parse_header(bytes, max_voxels, nullptr);
}

namespace {

// Chooses the largest step whose reconstruction stays at or under the RMS target:
// doubling until it fails, then bisection of the step's logarithm.
// `tick(done, total)` after every evaluation: the total is a guess while the bracket grows
// (the evaluations so far, one more, and the eight halvings) and exact after it.
template <typename Eval>
double search_step(double target, double first, const Eval& rmse_of, const ProgressFn& tick) {
  double good = 0, bad = 0;
  double s = first;
  int evaluations = 0;
  auto count = [&](int bisections_left) {
    ++evaluations;
    if (tick) tick(static_cast<std::uint64_t>(evaluations), static_cast<std::uint64_t>(evaluations + bisections_left));
  };
  for (int i = 0; i < 60 && (good == 0 || bad == 0); ++i) {
    const bool under = rmse_of(s) <= target;
    count(9);
    if (under) {
      good = s;
      s *= 2;
    } else {
      bad = s;
      s /= 2;
    }
  }
  if (good == 0) return 0;  // nothing meets the target
  if (bad == 0) return good;
  for (int i = 0; i < 8; ++i) {
    const double mid = std::sqrt(good * bad);
    const bool under = rmse_of(mid) <= target;
    count(7 - i);
    if (under) good = mid;
    else bad = mid;
  }
  return good;
}

}  // namespace

namespace {
// Whether the keys of `volume` under the bound are all zero on at least half of its rows
// (x lines): the empty space of a plume, not the noisy background of a CT head.
// Row by row, without a copy of the keys (the encoder holds enough of those).
bool mostly_zero_rows(const Volume& volume, double bound, int threads) {
  const std::size_t n = volume.size();
  if (n == 0 || volume.voxels.size() != n || !(bound > 0) || !std::isfinite(bound)) return false;  // refused later
  const Quantiser q = plan_max_error(volume, bound);
  const std::size_t width = volume.dims[0], rows = n / width;
  std::vector<std::uint8_t> zero(rows, 0);
  const std::size_t block = std::max<std::size_t>(1, (std::size_t{1} << 16) / width);  // rows a job
  parallel_for((rows + block - 1) / block, threads, [&](std::size_t b) {
    for (std::size_t r = b * block; r < std::min(rows, (b + 1) * block); ++r) {
      const double* row = volume.voxels.data() + r * width;
      zero[r] = std::all_of(row, row + width, [&](double v) { return key_of(q, v) == 0; });
    }
  });
  return 2 * static_cast<std::size_t>(std::count(zero.begin(), zero.end(), 1)) >= rows;
}

// Codes `volume` with `levels` and with the default depth and keeps the smaller file (the
// first on a tie); `split` is where the first encoding ends on the progress bar.
std::string smaller_of_levels(const Volume& volume, const EncodeOptions& o, int levels, double split,
                              EncodeStats* stats) {
  EncodeOptions few = o, deep = o;
  few.levels = levels;
  deep.levels = default_levels(volume.dims);
  few.progress = progress_part(o.progress, 0.0, split);
  deep.progress = progress_part(o.progress, split, 1.0);
  EncodeStats s_few, s_deep;
  std::string a = encode_vw(volume, few, &s_few), b = encode_vw(volume, deep, &s_deep);
  const bool first = a.size() <= b.size();
  if (stats) *stats = first ? s_few : s_deep;
  return first ? a : b;
}
}  // namespace

std::string encode_vw(const Volume& volume, const EncodeOptions& o, EncodeStats* stats) {
  // Lossless float32 bit patterns: sparse or rough data (a smoke plume: zeros and a few
  // thousand distinct floats) codes better with no transform at all (MED prediction on
  // the keys) than through a wavelet of bit patterns; smooth data the other way round.
  // Without a stated level count, both are tried and the smaller kept.
  if (o.mode == Mode::lossless && o.levels < 0 && plan_lossless(volume).kind == KeyKind::float32_bits)
    return smaller_of_levels(volume, o, 0, 0.4, stats);  // no transform: the cheaper one
  // Sparse data under a bound: one level of the wavelet, the rest of the approximation
  // band left to the context coder's prediction, codes a smoke plume 12-18 % smaller
  // than the default depth and decodes it faster (its approximation band is mostly zero
  // rows, which cost one flag each); dense data (the heads) gains 2-4 % in bytes that way
  // but decodes 16-35 % slower (docs/volwave.md §3 "Levels of sparse volumes"). So
  // without a stated level count, a volume whose keys are all zero on at least half of
  // its rows is also coded with one level, and the smaller file kept.
  if (o.mode == Mode::max_error && o.levels < 0 && wavelet_is_integer(o.wavelet) && default_levels(volume.dims) > 1 &&
      mostly_zero_rows(volume, o.bound, std::max(1, o.threads)))
    return smaller_of_levels(volume, o, 1, 0.5, stats);
  const std::size_t n = volume.size();
  if (n == 0 || volume.voxels.size() != n) throw bad_input("volume has {} voxels for dimensions {}x{}x{}", volume.voxels.size(),
                                                          volume.dims[0], volume.dims[1], volume.dims[2]);
  const int threads = std::max(1, o.threads);
  VwHeader h;
  h.mode = o.mode;
  h.wavelet = o.wavelet;
  h.type = volume.type;
  h.dims = volume.dims;
  h.spacing = volume.spacing;
  h.origin = volume.origin;
  h.direction = volume.direction;
  h.levels = o.levels < 0 ? default_levels(h.dims) : std::min(o.levels, kMaxLevels);
  h.bound = o.mode == Mode::lossless ? 0.0 : o.bound;
  std::vector<std::uint8_t> roi;
  if (!o.roi_mask.empty()) {
    if (o.mode != Mode::max_error) throw usage_error("a region of interest needs an L-infinity bound");
    if (o.roi_mask.size() != n) throw bad_input("region mask has {} voxels, the volume {}", o.roi_mask.size(), n);
    if (!(o.roi_bound > 0) || !(o.roi_bound <= o.bound))
      throw bad_input("the region's bound must be positive and at most the volume's bound {}, not {}", o.bound, o.roi_bound);
    roi = o.roi_mask;
    for (auto& m : roi) m = m ? 1 : 0;
    h.roi_bound = o.roi_bound;
  }
  if (o.mode != Mode::rmse && !wavelet_is_integer(o.wavelet))
    throw usage_error("{} coding needs an integer wavelet (haar or cdf53); cdf97 is for RMS targets", mode_name(o.mode));
  if (o.mode != Mode::lossless && (!(o.bound > 0) || !std::isfinite(o.bound)))
    throw bad_input("the error bound must be positive and finite, not {}", o.bound);

  // Where each phase ends on the bar (fractions of the whole, measured on a 361x433x361
  // MRI volume, 2 threads): the error of every truncation point (one reconstruction per
  // level) takes three quarters of a bounded encode; an RMS target's step search
  // re-quantises (with CDF 9/7 also reconstructs) about a dozen times before it.
  const double quantised_at = o.mode != Mode::rmse ? 0.04 : o.wavelet == Wavelet::cdf97 ? 0.55 : 0.38;
  const double rest = 1 - quantised_at;
  const double transformed_at = quantised_at + 0.03 * rest;
  const double coded_at = quantised_at + 0.13 * rest;
  const double measured_at = quantised_at + 0.9 * rest;
  auto reached = [&](double f) {
    if (o.progress) o.progress(static_cast<std::uint64_t>(1000 * f + 0.5), 1000);
  };

  std::vector<std::int64_t> coef;
  if (o.mode == Mode::lossless) {
    h.quantiser = plan_lossless(volume);
    coef = quantise(volume, h.quantiser, threads);
  } else if (o.mode == Mode::max_error) {
    h.quantiser = plan_max_error(volume, o.bound);
    coef = quantise(volume, h.quantiser, threads);
    if (!roi.empty()) {
      h.roi_step = plan_max_error(volume, o.roi_bound).step;
      for (std::size_t i = 0; i < n; ++i)
        if (roi[i]) coef[i] = std::llround((volume.voxels[i] - h.quantiser.offset) / h.roi_step);
    }
  } else if (o.wavelet != Wavelet::cdf97) {
    // RMS target with an integer wavelet: the voxel-domain step is the only loss.
    h.quantiser = plan_step(volume, o.bound * std::sqrt(12.0));
    std::vector<double> values;
    const double step = search_step(o.bound, h.quantiser.step, [&](double s) {
      Quantiser q = h.quantiser;
      q.step = s;
      dequantise(quantise(volume, q, threads), q, h.type, values, threads);
      return measure(volume.voxels, values, {}).rmse;
    }, progress_part(o.progress, 0.0, quantised_at));
    if (step == 0) throw bad_input("no quantiser step reaches RMS error {} for this volume", o.bound);
    h.quantiser.step = step;
    coef = quantise(volume, h.quantiser, threads);
  } else {
    // RMS target with CDF 9/7: quantise the (nearly orthonormal) coefficients.
    h.quantiser = plan_step(volume, 1.0);
    std::vector<double> c(n);
    for (std::size_t i = 0; i < n; ++i) c[i] = volume.voxels[i] - h.quantiser.offset;
    forward_3d(c, h.dims, h.levels, threads);
    double cmax = 0;
    for (double v : c) cmax = std::max(cmax, std::fabs(v));
    auto keys_for = [&](double delta) {
      std::vector<std::int64_t> k(n);
      for (std::size_t i = 0; i < n; ++i) k[i] = std::llround(c[i] / delta);
      return k;
    };
    const double step = search_step(o.bound, o.bound * std::sqrt(12.0), [&](double delta) {
      if (cmax / delta > 1e15) return 0.0;
      VwHeader t = h;
      t.quantiser.step = delta;
      return measure(volume.voxels, reconstruct(t, keys_for(delta), {}, threads), {}).rmse;
    }, progress_part(o.progress, 0.0, quantised_at));
    if (step == 0 || cmax / step > 1e15) throw bad_input("no quantiser step reaches RMS error {} for this volume", o.bound);
    h.quantiser.step = step;
    coef = keys_for(step);
  }
  reached(quantised_at);
  if (o.mode != Mode::rmse || o.wavelet != Wavelet::cdf97) forward_3d(coef, h.dims, h.levels, o.wavelet, threads);
  reached(transformed_at);

  std::uint64_t cmax = 0;
  for (auto v : coef) cmax = std::max<std::uint64_t>(cmax, static_cast<std::uint64_t>(v < 0 ? -v : v));
  h.max_exponent = bit_width(cmax) + 1;  // the approximation codes differences up to 2 cmax
  if (h.max_exponent > 60) throw bad_input("coefficients too large to code (2^{})", h.max_exponent);

  // Code every stream; streams are independent, so any thread count gives the same bytes.
  const auto bands = subbands(h.dims, h.levels);
  const auto by_chunk = streams_by_chunk(bands, h.levels);
  std::vector<const Stream*> all;
  for (const auto& c : by_chunk)
    for (const auto& s : c) all.push_back(&s);
  std::vector<std::string> coded(all.size());
  ProgressCounter streams_coded(progress_part(o.progress, transformed_at, coded_at), all.size());
  parallel_for(all.size(), threads, [&](std::size_t i) {
    coded[i] = encode_slab(coef.data(), h.dims, *all[i]->band, all[i]->parent, all[i]->slab, SlabCoding::smaller,
                           o.packed_slack);
    streams_coded.step();
  });
  streams_coded.finish();
  std::vector<std::string> chunks;
  std::size_t next = 0;
  for (const auto& c : by_chunk) {
    Writer w;
    for (std::size_t k = 0; k < c.size(); ++k) {
      // Version 5: varint lengths (most slabs of a small volume are under 128 bytes).
      if (h.version >= 5) w.varint(coded[next + k].size());
      else w.u32(static_cast<std::uint32_t>(coded[next + k].size()));
    }
    for (std::size_t k = 0; k < c.size(); ++k) w.out += coded[next + k];
    next += c.size();
    chunks.push_back(std::move(w.out));
  }

  // Error of every truncation point: decode with the finer bands zeroed.
  h.chunks.resize(chunks.size() + 1);
  std::vector<double> full;
  for (int k = 0; k <= h.levels; ++k) {
    std::vector<std::int64_t> part = coef;
    if (k < h.levels)
      for (const auto& b : bands)
        if (chunk_of(b, h.levels) > k)
          for (std::size_t z = b.lo[2]; z < b.hi[2]; ++z)
            for (std::size_t y = b.lo[1]; y < b.hi[1]; ++y)
              std::fill_n(&part[b.lo[0] + h.dims[0] * (y + h.dims[1] * z)], b.hi[0] - b.lo[0], 0);
    std::vector<double> rec = reconstruct(h, part, roi, threads);
    const Errors e = measure(volume.voxels, rec, roi);
    h.chunks[static_cast<std::size_t>(k)].max_error = e.max_error;
    h.chunks[static_cast<std::size_t>(k)].rmse = e.rmse;
    if (k == h.levels) full = std::move(rec);
    reached(coded_at + (measured_at - coded_at) * (k + 1) / (h.levels + 1));
  }
  coef.clear();
  coef.shrink_to_fit();

  // Outliers: voxels the stored type's rounding pushed past the bound, kept exactly.
  Writer ow;
  std::size_t outliers = 0;
  if (o.mode == Mode::max_error) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < n; ++i) {
      const double bound = (!roi.empty() && roi[i]) ? o.roi_bound : o.bound;
      if (std::fabs(volume.voxels[i] - full[i]) > bound) idx.push_back(i);
    }
    ow.varint(idx.size());
    std::size_t prev = 0;
    for (std::size_t i : idx) {
      ow.varint(i - prev);
      ow.f64(volume.voxels[i]);
      prev = i;
      full[i] = volume.voxels[i];
    }
    outliers = idx.size();
  } else {
    ow.varint(0);
  }
  chunks.push_back(std::move(ow.out));
  {
    const Errors e = measure(volume.voxels, full, roi);
    h.chunks.back().max_error = e.max_error;
    h.chunks.back().rmse = e.rmse;
  }
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    h.chunks[k].bytes = chunks[k].size();
    h.chunks[k].hash = checksum(chunks[k], h.version);
  }
  std::string out = write_header(h, roi);
  for (const auto& c : chunks) out += c;

  // The guarantee, checked on the bytes themselves by the decoder.
  const DecodeResult back = decode_vw(out, threads, -1, kMaxVoxels, progress_part(o.progress, measured_at, 1.0));
  const Errors e = measure(volume.voxels, back.volume.voxels, roi);
  if (o.mode == Mode::lossless) {
    for (std::size_t i = 0; i < n; ++i) {
      const double a = volume.voxels[i], b = back.volume.voxels[i];
      const bool same = (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0 || (a == b && a != 0);
      if (!same) throw runtime_failure("lossless check failed at voxel {}: {} decoded as {}", i, a, b);
    }
  } else if (o.mode == Mode::max_error && (e.max_error > o.bound || (!roi.empty() && e.roi_max_error > o.roi_bound))) {
    throw runtime_failure("decoded error {} exceeds the bound {}", e.max_error, o.bound);
  }
  if (stats) {
    stats->max_error = e.max_error;
    stats->rmse = e.rmse;
    stats->roi_max_error = e.roi_max_error;
    stats->outliers = outliers;
    stats->step = h.quantiser.step;
  }
  return out;
}

void reseal_vw(std::string& bytes, std::uint64_t max_voxels) {
  std::vector<std::uint8_t> roi;
  VwHeader h;
  try {
    h = parse_header(bytes, max_voxels, &roi, false);
  } catch (const Error&) {
    return;
  }
  std::size_t pos = h.header_bytes;
  for (auto& c : h.chunks) {
    if (bytes.size() - pos < c.bytes) break;
    c.hash = checksum(std::string_view(bytes).substr(pos, c.bytes), h.version);
    pos += c.bytes;
  }
  const std::string header = write_header(h, roi);
  if (header.size() == h.header_bytes) bytes.replace(0, header.size(), header);
}

SlabCensus slab_census(std::string_view bytes) {
  const VwHeader h = parse_header(bytes, kMaxVoxels, nullptr);
  const auto bands = subbands(h.dims, h.levels);
  const auto by_chunk = streams_by_chunk(bands, h.levels);
  SlabCensus census;
  std::size_t pos = h.header_bytes;
  for (int k = 0; k <= h.levels; ++k) {
    const std::uint64_t n = h.chunks[static_cast<std::size_t>(k)].bytes;
    if (bytes.size() - pos < n) break;
    const std::string_view chunk = bytes.substr(pos, n);
    const auto& streams = by_chunk[static_cast<std::size_t>(k)];
    const std::vector<std::string_view> parts = split_chunk(chunk, streams.size(), h.version, k);
    for (std::size_t i = 0; i < streams.size(); ++i) {
      const std::string_view part = parts[i];
      const auto mode = part.empty() ? 0xFF : static_cast<std::uint8_t>(part[0]);
      if (mode <= 2) {
        const Subband& b = *streams[i].band;
        const Slab& slab = streams[i].slab;
        census.slabs[mode] += 1;
        census.bytes[mode] += part.size();
        census.coefficients[mode] += (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (slab.z1 - slab.z0);
        // A packed slab's variant byte names its precision (fest-vw(5)).
        if (mode == 2 && part.size() >= 2) {
          const int bits = kRansBits - static_cast<std::uint8_t>(part[1]) / 6;
          if (bits >= kRansMinBits && bits <= kRansBits) census.packed_by_precision[static_cast<std::size_t>(bits - kRansMinBits)] += 1;
        }
      }
    }
    pos += n;
  }
  return census;
}

DecodeResult decode_vw(std::string_view bytes, int threads, int max_chunks, std::uint64_t max_voxels,
                       const ProgressFn& progress) {
  std::vector<std::uint8_t> roi;
  const VwHeader h = parse_header(bytes, max_voxels, &roi);
  // At least 2^19 voxels a thread: parallel_for starts its threads on every call, and a
  // decode makes dozens of calls (a slab loop per chunk, lifting steps per level and
  // axis). On the 66^3 plume (287,496 voxels) two threads took 0.94 ms against one
  // thread's 0.46 ms; the 7.1 M-voxel MRI head decodes 1.55x faster on two.
  const std::uint64_t voxels = static_cast<std::uint64_t>(h.dims[0]) * h.dims[1] * h.dims[2];
  threads = static_cast<int>(std::clamp<std::uint64_t>(voxels >> 19, 1, static_cast<std::uint64_t>(std::max(1, threads))));
  DecodeResult res;
  res.chunks_total = static_cast<int>(h.chunks.size());
  const int limit = max_chunks < 0 ? res.chunks_total : std::min(max_chunks, res.chunks_total);
  const auto bands = subbands(h.dims, h.levels);
  const auto by_chunk = streams_by_chunk(bands, h.levels);
  std::vector<double> buffer;
  reserve_large(buffer, h.dims[0] * h.dims[1] * h.dims[2]);
  buffer.resize(h.dims[0] * h.dims[1] * h.dims[2]);  // zero: the bands not decoded
  std::int64_t* coef = coefficients_in(buffer);
  std::size_t pos = h.header_bytes;
  int decoded = 0;
  // The bar: streams decoded up to half, the inverse transform the rest (as measured on a
  // 361x433x361 volume).
  std::size_t stream_total = 0;
  for (int k = 0; k <= h.levels && k < limit; ++k) stream_total += by_chunk[static_cast<std::size_t>(k)].size();
  ProgressCounter streams_decoded(progress_part(progress, 0.0, 0.5), stream_total);
  // Which rows hold non-zero coefficients, per level (the approximation's at h.levels):
  // the inverse transform skips the empty space around them.
  std::vector<RowList> nonzero_rows(static_cast<std::size_t>(h.levels) + 1);
  for (int k = 0; k <= h.levels && k < limit; ++k) {
    const ChunkInfo& info = h.chunks[static_cast<std::size_t>(k)];
    if (bytes.size() - pos < info.bytes) {
      res.truncated = true;
      break;
    }
    const std::string_view chunk = bytes.substr(pos, info.bytes);
    if (checksum(chunk, h.version) != info.hash) throw bad_input(".vw chunk {}: checksum mismatch (damaged data)", k);
    const auto& streams = by_chunk[static_cast<std::size_t>(k)];
    const std::vector<std::string_view> parts = split_chunk(chunk, streams.size(), h.version, k);
    std::vector<RowList> rows(streams.size());
    parallel_for(streams.size(), threads, [&](std::size_t s) {
      decode_slab(parts[s], coef, h.dims, *streams[s].band, streams[s].parent, streams[s].slab, h.max_exponent,
                  &rows[s], h.version);
      streams_decoded.step();
    });
    for (std::size_t s = 0; s < streams.size(); ++s) {
      RowList& to = nonzero_rows[static_cast<std::size_t>(streams[s].band->level)];
      to.insert(to.end(), rows[s].begin(), rows[s].end());
    }
    pos += info.bytes;
    ++decoded;
  }
  if (decoded == 0) {
    if (limit == 0) throw usage_error("at least the first chunk must be decoded");
    throw bad_input("truncated .vw: the coarsest level (chunk 0, {} bytes) is incomplete", h.chunks[0].bytes);
  }
  res.volume.dims = h.dims;
  res.volume.spacing = h.spacing;
  res.volume.origin = h.origin;
  res.volume.direction = h.direction;
  res.volume.type = h.type;
  streams_decoded.finish();
  reconstruct_in_place(h, buffer, roi, threads, &nonzero_rows);
  if (progress) progress(1000, 1000);
  res.volume.voxels = std::move(buffer);
  // Outliers apply to the full-resolution volume only.
  const std::size_t last = h.chunks.size() - 1;
  if (decoded == h.levels + 1 && limit > h.levels + 1) {
    const ChunkInfo& info = h.chunks[last];
    if (bytes.size() - pos < info.bytes) {
      res.truncated = true;
    } else {
      const std::string_view chunk = bytes.substr(pos, info.bytes);
      if (checksum(chunk, h.version) != info.hash) throw bad_input(".vw outlier chunk: checksum mismatch (damaged data)");
      Reader r(chunk, ".vw outlier chunk");
      const std::uint64_t count = r.varint();
      const std::size_t n = res.volume.voxels.size();
      if (count > n || count > chunk.size()) throw bad_input(".vw outlier chunk: {} outliers", count);
      std::size_t index = 0;
      for (std::uint64_t i = 0; i < count; ++i) {
        const std::uint64_t step = r.varint();
        if (step >= n - index) throw bad_input(".vw outlier chunk: index out of range");
        index += static_cast<std::size_t>(step);
        res.volume.voxels[index] = r.f64();
      }
      if (r.pos() != chunk.size()) throw bad_input(".vw outlier chunk: {} unused bytes", chunk.size() - r.pos());
      ++decoded;
    }
  } else if (decoded < limit) {
    res.truncated = true;
  }
  res.chunks_decoded = decoded;
  res.max_error = h.chunks[static_cast<std::size_t>(decoded - 1)].max_error;
  res.rmse = h.chunks[static_cast<std::size_t>(decoded - 1)].rmse;
  return res;
}

}  // namespace fest::wavelet
