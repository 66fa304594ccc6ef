#include "sampling/resize.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "sampling/float_image.hpp"
#include "sampling/separable_pass.hpp"

namespace fest::sampling {

namespace {

constexpr std::int64_t max_pixels = std::int64_t{1} << 31;

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
  for (std::size_t i = 0; i < out.data.size(); ++i) {
    const auto ch = i % static_cast<std::size_t>(c);
    out.data[i] = std::clamp(out.data[i], lo[ch], hi[ch]);
  }
}

}  // namespace

Image resize(const Image& in, int width, int height, const ResizeOptions& options) {
  check_size(width, height);
  check_supported(in);
  const cv::Mat& m = in.pixels;
  if (static_cast<std::int64_t>(m.cols) * m.rows > max_pixels)
    throw bad_input("resize: input size {}x{} exceeds 2^31 pixels", m.cols, m.rows);
  const int threads = resolve_threads(options.threads);
  const WeightTable tx = make_weight_table(m.cols, width, options.kernel, options.shift_x, options.edge);
  const WeightTable ty = make_weight_table(m.rows, height, options.kernel, options.shift_y, options.edge);

  Encoding enc;
  enc.decode_srgb = options.linear_light && in.color_space == ColorSpace::srgb;
  enc.premultiply = options.premultiply_alpha && alpha_channel(m.channels()) >= 0;
  const FloatImage work = to_working(in, enc);

  // The axis with the larger reduction goes first: the intermediate image is smaller.
  const double sx = static_cast<double>(width) / m.cols, sy = static_cast<double>(height) / m.rows;
  FloatImage out = sx <= sy ? resample_columns(resample_rows(work, tx, threads), ty, threads)
                            : resample_rows(resample_columns(work, ty, threads), tx, threads);

  const bool integer = m.depth() != CV_32F;
  if (options.clamp == ClampMode::range || (options.clamp == ClampMode::automatic && integer))
    clamp_to_input_range(work, integer, out);

  Image result;
  result.color_space = in.color_space;
  result.pixels = from_working(out, m.depth(), enc);
  return result;
}

}  // namespace fest::sampling
