#pragma once
// 1-D transfer functions (docs/volrender.md "Transfer function and compositing"):
// piecewise-linear RGBA over the data value, converted to an extinction coefficient
//   tau(v) = -ln(1 - a(v)) / ds0   (opacity mode: a = opacity of a segment of length ds0)
//   tau(v) = a(v) / ds0            (extinction mode)
// and tabulated in 4096 bins over the data range. Between bins the table is linear, so a
// linear transfer function is represented exactly; T(s) = int tau and K(s) = int tau c
// are integrated exactly over that piecewise-linear table (pre-integration, Engel, Kraus &
// Ertl 2001).

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace fest::raycast {

struct ControlPoint {
  double value;  // data units
  double r, g, b, a;
};

enum class OpacityMode { opacity, extinction };

// Parses CSV rows "value,r,g,b,a" (an optional header line, '#' comments; a value may end
// in '%' = percent of [lo, hi]) or ParaView's colour-map JSON (RGBPoints, optional Points).
// Throws std::invalid_argument with a message naming the line for malformed text, values
// not increasing, fewer than 2 points, colours outside [0,1], or opacity > 1 in opacity mode.
std::vector<ControlPoint> parse_transfer_function(std::string_view text, double lo, double hi, OpacityMode mode);

// Built-in presets (grey, ct-bone, ct-skin-bone, mri, flow, rainbow, contour-only) over the
// data range [lo, hi]; throws std::invalid_argument for an unknown name.
std::vector<ControlPoint> preset_transfer_function(const std::string& name, double lo, double hi);
bool is_preset(const std::string& name);

class TransferFunction {
 public:
  static constexpr int kBins = 4096;
  TransferFunction() = default;
  // tf_unit: ds0 in voxel units.
  TransferFunction(std::vector<ControlPoint> points, double lo, double hi, OpacityMode mode, double tf_unit);

  struct Sample {
    double tau;                   // extinction per voxel unit
    std::array<double, 3> rgb;    // colour
  };
  // Inline: the ray caster calls it for every sample. One interleaved table row per bin
  // (tau, r, g, b), so a lookup touches one or two cache lines.
  Sample at(double v) const {
    const double x = position(v);
    const int k = x < kBins - 2 ? static_cast<int>(x) : kBins - 2;
    const double w = x - k;
    const double* a = &lut_[4 * static_cast<std::size_t>(k)];
    const double* b = a + 4;
#if defined(__SSE2__)
    // the same a + w (b - a) per channel, two channels per register
    const __m128d wv = _mm_set1_pd(w);
    const __m128d a01 = _mm_loadu_pd(a), a23 = _mm_loadu_pd(a + 2);
    const __m128d v01 = _mm_add_pd(a01, _mm_mul_pd(wv, _mm_sub_pd(_mm_loadu_pd(b), a01)));
    const __m128d v23 = _mm_add_pd(a23, _mm_mul_pd(wv, _mm_sub_pd(_mm_loadu_pd(b + 2), a23)));
    double r[4];
    _mm_storeu_pd(r, v01);
    _mm_storeu_pd(r + 2, v23);
    return {r[0], {r[1], r[2], r[3]}};
#else
    return {a[0] + w * (b[0] - a[0]), {a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2]), a[3] + w * (b[3] - a[3])}};
#endif
  }
  // T(v) and K(v) (per voxel unit, from lo).
  double integral_tau(double v) const;
  std::array<double, 3> integral_tau_color(double v) const;
  // True when tau is exactly 0 everywhere on [vlo, vhi] (empty-space skipping).
  bool transparent(double vlo, double vhi) const;
  double lo() const { return lo_; }
  double hi() const { return hi_; }

 private:
  double position(double v) const {  // continuous bin coordinate in [0, kBins - 1]
    const double x = (v - lo_) * inv_width_;  // a product: a division per sample was its latency
    return x < 0.0 ? 0.0 : x > kBins - 1 ? static_cast<double>(kBins - 1) : x;
  }
  std::vector<double> tau_, r_, g_, b_;
  std::vector<double> lut_;                        // tau, r, g, b per bin, interleaved
  std::vector<double> T_;                          // integral of tau up to each bin
  std::vector<std::array<double, 3>> K_;           // integral of tau*c up to each bin
  std::vector<int> nonzero_prefix_;                // bins with tau > 0 before each bin
  double lo_ = 0, hi_ = 1, width_ = 1, inv_width_ = 1;
};

}  // namespace fest::raycast
