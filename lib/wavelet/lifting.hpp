#pragma once
// Separable 3-D discrete wavelet transforms by lifting (docs/volwave.md §2): the integer
// Haar (S-transform) and CDF 5/3 (JPEG 2000's reversible filter) on 64-bit integers,
// which invert exactly, and the CDF 9/7 on doubles, scaled to be nearly orthonormal.
// Lines of any length are handled by whole-sample symmetric extension; a line of
// length 1 is left alone, so 2-D volumes (one slice) work unchanged.
//
// Layout (Mallat's pyramid): level 0 transforms the whole grid along x, y and z and
// stores each line's low-pass half first; level l+1 transforms the low-low-low corner
// of level l. Subbands are addressed by `Subband`.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fest::wavelet {

enum class Wavelet : std::uint8_t { haar = 0, cdf53 = 1, cdf97 = 2 };

const char* wavelet_name(Wavelet w) noexcept;  // "haar", "cdf53", "cdf97"
bool parse_wavelet(const char* name, Wavelet& out) noexcept;  // also "53", "97"
bool wavelet_is_integer(Wavelet w) noexcept;  // haar and cdf53

using Dims = std::array<std::size_t, 3>;

// Extent of the low-pass corner after `level` levels: ceil(n / 2^level) per axis.
Dims level_dims(const Dims& dims, int level) noexcept;

// The number of levels fest uses by default: halve until no axis exceeds 8 samples
// (at most 8 levels).
int default_levels(const Dims& dims) noexcept;

// One block of coefficients: the voxels [lo, hi) of the pyramid layout.
struct Subband {
  int level = 0;        // 0: finest details; `levels` with orientation 0: the coarse approximation
  int orientation = 0;  // bit a set: high-pass along axis a (0 = low-low-low)
  Dims lo{0, 0, 0}, hi{0, 0, 0};
  std::size_t size() const noexcept { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

// The subbands in coding order: the approximation first, then the seven detail bands
// of each level from the coarsest to the finest. Empty bands (an axis of length 1) are
// left out. `chunk_of` gives for every listed band the truncation unit it belongs to
// (0: approximation, k: the details of level levels-k).
std::vector<Subband> subbands(const Dims& dims, int levels);
int chunk_of(const Subband& band, int levels) noexcept;

// 1-D lifting on one line of n samples: `line` in, low half then high half out.
// `scratch` needs n elements.
void forward_line(std::int64_t* line, std::size_t n, Wavelet w, std::int64_t* scratch);
void inverse_line(std::int64_t* line, std::size_t n, Wavelet w, std::int64_t* scratch);
void forward_line_97(double* line, std::size_t n, double* scratch);
void inverse_line_97(double* line, std::size_t n, double* scratch);

// 3-D transforms in place (x fastest). Integer wavelets only for the int64 overloads,
// cdf97 only for the double ones. `threads` >= 1.
void forward_3d(std::vector<std::int64_t>& data, const Dims& dims, int levels, Wavelet w, int threads);
void inverse_3d(std::vector<std::int64_t>& data, const Dims& dims, int levels, Wavelet w, int threads);
// The same on a buffer of dims[0] * dims[1] * dims[2] values.
void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads);

// Rows (x lines) of the pyramid are numbered y + dims[1] * z.
using RowList = std::vector<std::size_t>;

// The inverse integer transform knowing which rows hold non-zero coefficients:
// nonzero_rows[l] (l < levels) lists the rows holding non-zero detail coefficients of
// level l, nonzero_rows[levels] those of the approximation; every other row of a
// level's bands must be zero. The transform follows which rows can be non-zero through
// every step (a sample depends only on samples near half its index), and lines and
// planes of rows known to be zero -- zero in, zero out -- are skipped without being
// looked at (docs/volwave.md §4: the empty space of a plume).
// `row_spans`, when given, receives per row the columns [begin, end) outside which the
// result's row is known to be zero (begin == end: all of it).
struct RowSpan {
  std::uint32_t begin = 0, end = 0;
};
void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads,
                const std::vector<RowList>& nonzero_rows, std::vector<RowSpan>* row_spans = nullptr);
void forward_3d(std::vector<double>& data, const Dims& dims, int levels, int threads);
void inverse_3d(std::vector<double>& data, const Dims& dims, int levels, int threads);

}  // namespace fest::wavelet
