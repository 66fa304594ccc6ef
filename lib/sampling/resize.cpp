#include "sampling/resize.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "sampling/float_image.hpp"
#include "sampling/frequency_response.hpp"
#include "sampling/line_filters.hpp"
#include "sampling/local_clamp.hpp"
#include "sampling/separable_pass.hpp"

namespace fest::sampling {

namespace {

constexpr std::int64_t max_pixels = std::int64_t{1} << 31;
// Alias terms in A_r(f) = Σ_k R(f + k)² for the spectral duals: R decays at least like
// 1/f² for every finite display kernel, so the tail beyond 200 is below 1e-7.
constexpr int autocorrelation_terms = 200;

void check_size(int width, int height) {
  if (width <= 0 || height <= 0) throw usage_error("resize: output size {}x{} must be positive", width, height);
  if (static_cast<std::int64_t>(width) * height > max_pixels)
    throw usage_error("resize: output size {}x{} exceeds 2^31 pixels", width, height);
}

// ClampMode::range: integer inputs clamp to their representable [0, 1]; float inputs to
// each channel's [min, max] in the working domain.
void clamp_to_input_range(const FloatImage& in, bool integer, FloatImage& out) {
  const int c = in.channels;
  std::vector<float> lo(static_cast<std::size_t>(c), integer ? 0.0f : std::numeric_limits<float>::infinity());
  std::vector<float> hi(static_cast<std::size_t>(c), integer ? 1.0f : -std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; !integer && i < in.data.size(); ++i) {
    const auto ch = i % static_cast<std::size_t>(c);
    lo[ch] = std::min(lo[ch], in.data[i]);
    hi[ch] = std::max(hi[ch], in.data[i]);
  }
  if (integer) {  // one range for every channel: a loop without the channel index
    for (float& v : out.data) v = std::min(std::max(v, 0.0f), 1.0f);
    return;
  }
  for (std::size_t i = 0; i < out.data.size(); ++i) {
    const auto ch = i % static_cast<std::size_t>(c);
    out.data[i] = std::clamp(out.data[i], lo[ch], hi[ch]);
  }
}

// The correction of a dual prefilter on the output grid along one axis (§2.2): the
// discrete filter with DTFT 1/A_r, recursive for the B-spline displays, spectral otherwise.
void dual_correction(FloatImage& img, Axis axis, const Kernel& r, double epsilon, int threads) {
  if (r.name == "triangle") return recursive_inverse(img, axis, {std::sqrt(3.0) - 2}, threads);
  if (r.name == "bspline")
    return recursive_inverse(img, axis, {-0.5352804307964382, -0.1225546151923267, -0.009148694809608277}, threads);
  spectral_filter(
      img, axis,
      [&](double f) {
        double a = 0;
        for (int k = -autocorrelation_terms; k <= autocorrelation_terms; ++k) a += std::pow(frequency_response(r, f + k), 2);
        return 1 / std::max(a, epsilon);
      },
      threads);
}

// One axis of the resize with one kernel.
FloatImage resample_axis(const FloatImage& in, Axis axis, int n_out, const Kernel& k, double shift, const ResizeOptions& o,
                         int threads) {
  const int n_in = axis == Axis::x ? in.width : in.height;
  if (k.name == "sinc") {
    if (shift != 0) throw usage_error("kernel 'sinc' does not take --shift");
    if (o.edge != EdgeMode::reflect && o.edge != EdgeMode::clamp)
      throw usage_error("kernel 'sinc' extends the image by mirroring only (--edge clamp or reflect)");
    return spectral_resample(in, axis, n_out, threads);
  }
  const bool dual = !k.reconstruction.empty();
  const Kernel filter = dual ? make_kernel(k.reconstruction) : k;
  const WeightTable t = make_weight_table(n_in, n_out, filter, shift, o.edge);
  FloatImage out = axis == Axis::x ? resample_rows(in, t, threads) : resample_columns(in, t, threads);
  if (dual) dual_correction(out, axis, filter, o.dual_epsilon, threads);
  return out;
}

void for_colour(FloatImage& img, float (*f)(float)) {
  const int c = img.channels, a = alpha_channel(c);
  for (std::size_t i = 0; i < img.data.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(c)) != a) img.data[i] = f(img.data[i]);
}

float compress(float x) { return x > 1 ? 1 + std::log(x) : x; }
float expand(float y) { return y > 1 ? std::exp(y - 1) : y; }

}  // namespace

void compress_highlights(FloatImage& img) { for_colour(img, compress); }
void expand_highlights(FloatImage& img) { for_colour(img, expand); }

FloatImage resize_working(const FloatImage& work, int width, int height, const ResizeOptions& options, bool integer,
                          bool integer_output) {
  check_size(width, height);
  const int threads = resolve_threads(options.threads);
  const Kernel& kx = options.kernel;
  const Kernel& ky = options.kernel_y ? *options.kernel_y : options.kernel;

  FloatImage in = work;
  if (options.hicomp) compress_highlights(in);
  // The axis with the larger reduction goes first: the intermediate image is smaller.
  const double sx = static_cast<double>(width) / in.width, sy = static_cast<double>(height) / in.height;
  FloatImage out;
  if (sx <= sy)
    out = resample_axis(resample_axis(in, Axis::x, width, kx, options.shift_x, options, threads), Axis::y, height, ky,
                        options.shift_y, options, threads);
  else
    out = resample_axis(resample_axis(in, Axis::y, height, ky, options.shift_y, options, threads), Axis::x, width, kx,
                        options.shift_x, options, threads);

  if (options.clamp == ClampMode::local)
    clamp_to_local_range(in, options.shift_x, options.shift_y, out);
  else if (options.clamp == ClampMode::range || (options.clamp == ClampMode::automatic && integer_output))
    clamp_to_input_range(in, integer, out);
  if (options.hicomp) expand_highlights(out);
  return out;
}

Image resize(const Image& in, int width, int height, const ResizeOptions& options) {
  check_size(width, height);
  check_supported(in);
  const cv::Mat& m = in.pixels;
  if (static_cast<std::int64_t>(m.cols) * m.rows > max_pixels)
    throw bad_input("resize: input size {}x{} exceeds 2^31 pixels", m.cols, m.rows);

  const int depth = options.output_depth < 0 ? m.depth() : options.output_depth;
  const bool float_in = m.depth() == CV_32F, float_out = depth == CV_32F;
  Encoding decode;
  decode.decode_srgb = options.linear_light && in.color_space == ColorSpace::srgb;
  decode.premultiply = options.premultiply_alpha && alpha_channel(m.channels()) >= 0;
  FloatImage out;
  const bool streaming = !options.hicomp && options.clamp != ClampMode::local && options.kernel.reconstruction.empty() &&
                         options.kernel.name != "sinc" && !options.kernel_y;
  if (streaming) {
    // The common case: rows first, straight from the stored pixels (no float copy of
    // the input), then columns; the clamp needs only the [0, 1] range of integer input.
    const int threads = resolve_threads(options.threads);
    const WeightTable tx = make_weight_table(m.cols, width, options.kernel, options.shift_x, options.edge);
    const WeightTable ty = make_weight_table(m.rows, height, options.kernel, options.shift_y, options.edge);
    // Columns first moves the larger share of the work into the contiguous, vectorised
    // column loop (counted ~4x cheaper per tap than the per-pixel row loop); it needs taps
    // that move forward, so wrap and reflect edges keep rows first.
    const double c = m.channels();
    const double taps_x = static_cast<double>(tx.index.size()) / width, taps_y = static_cast<double>(ty.index.size()) / height;
    const double rows_first = double(m.rows) * width * taps_x * c + double(width) * c * height * taps_y / 4;
    const double cols_first = double(m.cols) * c * height * taps_y / 4 + double(height) * width * taps_x * c;
    const bool forward_taps = options.edge == EdgeMode::clamp || options.edge == EdgeMode::zero;
    if (forward_taps && cols_first < rows_first)
      out = resample_rows(resample_columns_decoded(m, decode, ty, threads), tx, threads);
    else
      out = resample_columns(resample_rows_decoded(m, decode, tx, threads), ty, threads);
    if (options.clamp == ClampMode::range || (options.clamp == ClampMode::automatic && !float_out)) {
      if (float_in)
        clamp_to_input_range(to_working(in, decode), false, out);
      else
        clamp_to_input_range(FloatImage(1, 1, m.channels()), true, out);
    }
  } else {
    out = resize_working(to_working(in, decode), width, height, options, !float_in, !float_out);
  }

  // Float outputs hold linear light; integer outputs are sRGB codes when the input was
  // sRGB or (linear) float, and keep the input's coding when it was linear integers.
  Encoding encode = decode;
  encode.decode_srgb = options.linear_light && !float_out && (in.color_space == ColorSpace::srgb || float_in);
  encode.dither = options.dither;
  encode.seed = options.seed;
  Image result;
  result.color_space = float_out ? (decode.decode_srgb ? ColorSpace::linear : in.color_space)
                                 : (encode.decode_srgb ? ColorSpace::srgb : in.color_space);
  result.pixels = from_working(out, depth, encode);
  return result;
}

}  // namespace fest::sampling
