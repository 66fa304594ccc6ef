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
#include "sampling/streamed_resize.hpp"

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

// Each channel of `out` clamped to [lo, hi] of that channel.
void clamp_to_range(const ChannelRange& r, FloatImage& out) {
  const auto c = static_cast<std::size_t>(out.channels);
  for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = std::clamp(out.data[i], r.lo[i % c], r.hi[i % c]);
}

// Each channel's [min, max] over the working values of a float input.
ChannelRange input_range(const FloatImage& in) {
  const auto c = static_cast<std::size_t>(in.channels);
  ChannelRange r{std::vector<float>(c, std::numeric_limits<float>::infinity()),
                 std::vector<float>(c, -std::numeric_limits<float>::infinity())};
  for (std::size_t i = 0; i < in.data.size(); ++i) {
    r.lo[i % c] = std::min(r.lo[i % c], in.data[i]);
    r.hi[i % c] = std::max(r.hi[i % c], in.data[i]);
  }
  return r;
}

// ClampMode::range: integer inputs clamp to their representable [0, 1]; float inputs to
// each channel's [min, max] in the working domain.
void clamp_to_input_range(const FloatImage& in, bool integer, FloatImage& out) {
  if (integer) {  // one range for every channel: a loop without the channel index
    for (float& v : out.data) v = std::min(std::max(v, 0.0f), 1.0f);
    return;
  }
  clamp_to_range(input_range(in), out);
}

// The correction of a dual prefilter on the output grid along one axis (docs/resample.md "The 1-D chain and the optimal prefilter"): the
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
    if (shift != 0) throw usage_error("kernel 'sinc' does not take a sub-pixel shift");
    if (o.edge != EdgeMode::reflect && o.edge != EdgeMode::clamp)
      throw usage_error("kernel 'sinc' extends the image by mirroring only (edge mode clamp or reflect)");
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
  check_supported(in);
  return resize(MatRows(in.pixels), in.color_space, width, height, options);
}

Image resize(const StoredRows& in, ColorSpace color_space, int width, int height, const ResizeOptions& options) {
  check_size(width, height);
  const int type = in.type(), c = CV_MAT_CN(type), in_depth = CV_MAT_DEPTH(type);
  if (in.width() <= 0 || in.height() <= 0) throw bad_input("resize: the input image is empty");
  if (c < 1 || c > 4) throw bad_input("resize: {} channels are not supported (1 to 4)", c);
  if (in_depth != CV_8U && in_depth != CV_16U && in_depth != CV_32F)
    throw bad_input("resize: pixel depth {} is not supported (8-bit, 16-bit or 32-bit float)", in_depth);
  if (static_cast<std::int64_t>(in.width()) * in.height() > max_pixels)
    throw bad_input("resize: input size {}x{} exceeds 2^31 pixels", in.width(), in.height());

  const int depth = options.output_depth < 0 ? in_depth : options.output_depth;
  const bool float_in = in_depth == CV_32F, float_out = depth == CV_32F;
  Encoding decode;
  decode.decode_srgb = options.linear_light && color_space == ColorSpace::srgb;
  decode.premultiply = options.premultiply_alpha && alpha_channel(c) >= 0;
  FloatImage out;
  const bool streaming = !options.hicomp && options.clamp != ClampMode::local && options.kernel.reconstruction.empty() &&
                         options.kernel.name != "sinc" && !options.kernel_y;
  // The whole stored image, for the paths that need it (read only when they run).
  auto whole = [&] {
    Image img;
    cv::Mat owner(in.height(), in.width(), type);
    const cv::Mat view = in.rows(0, in.height(), owner.data);
    img.pixels = view.data == owner.data ? owner : view;
    img.color_space = color_space;
    return img;
  };
  if (streaming) {
    // The common case: both passes streamed over the stored rows through a ring
    // (docs/resample.md, "Streaming"); the clamp needs only the [0, 1] range of integer
    // input, or the decoded float input's range, gathered on the way.
    const int threads = resolve_threads(options.threads);
    const WeightTable tx = make_weight_table(in.width(), width, options.kernel, options.shift_x, options.edge);
    const WeightTable ty = make_weight_table(in.height(), height, options.kernel, options.shift_y, options.edge);
    // Columns first moves the larger share of the work into the contiguous, vectorised
    // column loop (counted ~4x cheaper per tap than the per-pixel row loop). Reflect and
    // wrap edges keep rows first, as they always have: the order changes float rounding.
    const double cn = c;
    const double taps_x = static_cast<double>(tx.index.size()) / width, taps_y = static_cast<double>(ty.index.size()) / height;
    const double rows_first = double(in.height()) * width * taps_x * cn + double(width) * cn * height * taps_y / 4;
    const double cols_first = double(in.width()) * cn * height * taps_y / 4 + double(height) * width * taps_x * cn;
    const bool forward_edges = options.edge == EdgeMode::clamp || options.edge == EdgeMode::zero;
    const bool clamp_range = options.clamp == ClampMode::range || (options.clamp == ClampMode::automatic && !float_out);
    ChannelRange range;
    std::optional<FloatImage> streamed =
        resize_streamed(in, decode, StreamedPasses{&tx, &ty, forward_edges && cols_first < rows_first}, threads,
                        clamp_range && float_in ? &range : nullptr);
    if (streamed) {
      out = std::move(*streamed);
    } else {  // wrap edges: the last outputs' taps jump back, so the whole image takes both passes
      const Image img = whole();
      out = resample_columns(resample_rows_decoded(img.pixels, decode, tx, threads), ty, threads);
      if (clamp_range && float_in) range = input_range(to_working(img, decode));
    }
    if (clamp_range) {
      if (float_in)
        clamp_to_range(range, out);
      else
        clamp_to_input_range(FloatImage(1, 1, c), true, out);
    }
  } else {
    out = resize_working(to_working(whole(), decode), width, height, options, !float_in, !float_out);
  }

  // Float outputs hold linear light; integer outputs are sRGB codes when the input was
  // sRGB or (linear) float, and keep the input's coding when it was linear integers.
  Encoding encode = decode;
  encode.decode_srgb = options.linear_light && !float_out && (color_space == ColorSpace::srgb || float_in);
  encode.dither = options.dither;
  encode.seed = options.seed;
  Image result;
  result.color_space = float_out ? (decode.decode_srgb ? ColorSpace::linear : color_space)
                                 : (encode.decode_srgb ? ColorSpace::srgb : color_space);
  result.pixels = from_working(out, depth, encode);
  return result;
}

}  // namespace fest::sampling
