#pragma once
// The .vw file (man/man5/fest-vw.5, docs/volwave.md §5): a volume coded by volwave.
// Bytes <-> types only; no I/O.
//
//   header   magic "\x89VW\r\n\x1a\n\x04" (format version 4; version 3 is still read), mode, wavelet, levels, stored type, key kind,
//            largest coded exponent, dimensions, spacing, origin, direction, quantiser
//            step and offset, the requested bound, and a table with one row per chunk:
//            byte length, FNV-1a hash, and the L-infinity and RMS error of a volume
//            decoded from the chunks up to and including this one (measured by the
//            encoder); the header ends with its own FNV-1a hash.
//   chunks   0: the approximation band; 1..levels: the seven detail bands of one level,
//            coarsest first; last: the outliers (voxels stored exactly).
// A file cut anywhere after the first chunk still decodes: the missing finer detail
// bands count as zero, which gives a smoother volume, and the table says its error.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/progress_callback.hpp"
#include "core/volume.hpp"
#include "wavelet/lifting.hpp"
#include "wavelet/quantiser.hpp"

namespace fest::wavelet {

// The format version written, the magic's last byte. Version 3 files (no packed slabs)
// and version 4 files (packed slabs at full table precision, FNV-1a checksums) are
// still read; `volwave info` reports a file's own version.
inline constexpr int kVwFormatVersion = 5;
inline constexpr int kVwOldestReadVersion = 3;

// The encoder's choice per detail-band slab (docs/volwave.md §4 "Packed slabs"): the
// packed coding when its bytes are at most (1 + slack) times the smaller context coding.
// The default (volwave --favour speed); slack 0 packs only where packing is not larger
// (--favour size: the smallest file).
inline constexpr double kPackedSlackSpeed = 0.50;

enum class Mode : std::uint8_t { lossless = 0, max_error = 1, rmse = 2 };
const char* mode_name(Mode m) noexcept;  // "lossless", "max-error", "rmse"

struct EncodeOptions {
  Mode mode = Mode::max_error;
  double bound = 0.0;     // max_error: L-infinity bound; rmse: the RMS error to stay under
  Wavelet wavelet = Wavelet::cdf53;
  int levels = -1;        // -1: default_levels()
  int threads = 1;
  // Packed slabs: the slack allowed (kPackedSlackSpeed); < 0 never packs (the bytes
  // version 3's coders alone give, in a version-4 container).
  double packed_slack = kPackedSlackSpeed;
  // Region of interest coded with its own, tighter L-infinity bound (max_error mode):
  // the voxels whose mask byte is non-zero (mask empty: no region).
  std::vector<std::uint8_t> roi_mask;
  double roi_bound = 0.0;
  // Thousandths of the whole: quantiser (and its step search), transform, coding, the
  // error of every truncation point, the check by decoding.
  ProgressFn progress;
};

struct ChunkInfo {
  std::uint64_t bytes = 0;
  std::uint64_t hash = 0;
  double max_error = 0.0;  // of the volume decoded through this chunk
  double rmse = 0.0;
};

struct VwHeader {
  int version = kVwFormatVersion;  // the magic's last byte
  Mode mode = Mode::max_error;
  Wavelet wavelet = Wavelet::cdf53;
  int levels = 0;
  ScalarType type = ScalarType::f32;
  Quantiser quantiser;         // step, offset, key kind
  double roi_step = 0.0;       // > 0: the region's step (max_error with a region)
  int max_exponent = 0;
  Dims dims{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double bound = 0.0;          // as requested (0 for lossless)
  double roi_bound = 0.0;
  std::vector<ChunkInfo> chunks;
  std::size_t header_bytes = 0;  // where chunk 0 starts

  std::uint64_t total_bytes() const noexcept;
};

// What encoding measured on its own output, decoded again (the guarantee checked).
struct EncodeStats {
  double max_error = 0.0;
  double rmse = 0.0;
  double roi_max_error = 0.0;
  std::size_t outliers = 0;
  double step = 0.0;
};

// Throws bad_input for data the mode cannot code (NaN with a bound, ...), and
// Status::failure if the decoded output breaks the bound (which would be a bug).
std::string encode_vw(const Volume& volume, const EncodeOptions& options, EncodeStats* stats = nullptr);

// Parses and checks the header. Throws bad_input for a damaged or truncated header.
// `max_voxels` caps the dimensions a header may claim (decoders of untrusted bytes,
// fuzzers).
VwHeader read_vw_header(std::string_view bytes, std::uint64_t max_voxels = kMaxVoxels);

struct DecodeResult {
  Volume volume;
  int chunks_decoded = 0;   // complete chunks used
  int chunks_total = 0;
  bool truncated = false;   // the file ended before its last chunk
  double max_error = 0.0;   // from the header table, for the chunks used
  double rmse = 0.0;
};

// Decodes all complete chunks (at most `max_chunks`, -1 = all). A file whose
// approximation chunk is incomplete, or a chunk whose hash does not match, throws
// bad_input.
// `progress` hears thousandths: the streams decoded, then the inverse transform.
DecodeResult decode_vw(std::string_view bytes, int threads = 1, int max_chunks = -1,
                       std::uint64_t max_voxels = kMaxVoxels, const ProgressFn& progress = {});

// How the coefficient slabs of the complete chunks are coded (`volwave info`): per slab
// mode (0 adaptive, 1 static, 2 packed; fest-vw(5)) the number of slabs, their bytes and
// the coefficients they hold. Throws bad_input for a damaged header or chunk table.
struct SlabCensus {
  std::array<std::uint64_t, 3> slabs{}, bytes{}, coefficients{};
  // Packed slabs per rANS table precision (index bits - 5, bits 5..11; version 5).
  std::array<std::uint64_t, 7> packed_by_precision{};
};
SlabCensus slab_census(std::string_view bytes);

// Recomputes the header's and the complete chunks' hashes in place (fuzzers use it to
// get past the checksums to the parsers behind them). Leaves unparsable bytes alone.
void reseal_vw(std::string& bytes, std::uint64_t max_voxels = kMaxVoxels);

}  // namespace fest::wavelet
