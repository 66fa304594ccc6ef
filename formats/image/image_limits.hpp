#pragma once
// Plausibility limits shared by every image header parser: the first line of defence
// against a 40-byte file that claims to be 100000 x 100000 pixels.

#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"

namespace fest::formats::image_detail {

// At most 2^30 sample values in one image (4 GiB as float): beyond that a header is
// far more likely to be corrupt than real.
inline constexpr std::uint64_t max_image_values = std::uint64_t{1} << 30;

// The largest expansion a compressed pixel stream can justify. Deflate tops out near
// 1032:1, LZW with 12-bit codes near 2700:1, so 4096 bytes out per byte in leaves
// headroom for every codec PNG, TIFF and EXR use while refusing a tiny file that asks
// for gigabytes. The slack lets very small but legal files (a 1-pixel constant image)
// through.
inline constexpr std::uint64_t max_expansion = 4096;
inline constexpr std::uint64_t expansion_slack = std::uint64_t{1} << 20;

inline std::uint64_t bytes_per_value(const ImageHeader& h) { return h.bits <= 8 ? 1 : h.bits / 8; }

// Checks sizes are positive and bounded; `what` names the format for the message.
inline void check_dimensions(const ImageHeader& h, const char* what) {
  if (h.width <= 0 || h.height <= 0)
    throw bad_input("{} header: image size {} x {} is not positive", what, h.width, h.height);
  if (h.channels < 1 || h.channels > 4)
    throw bad_input("{} header: {} channels (1 to 4 supported)", what, h.channels);
  const std::uint64_t values =
      std::uint64_t(h.width) * std::uint64_t(h.height) * std::uint64_t(h.channels);
  if (values > max_image_values)
    throw bad_input("{} header: {} x {} x {} channels exceeds the limit of 2^30 values", what,
                    h.width, h.height, h.channels);
}

// For compressed formats: refuses a decoded size the input could not hold.
inline void check_expansion(const ImageHeader& h, std::size_t input_bytes, const char* what) {
  const std::uint64_t decoded = std::uint64_t(h.width) * std::uint64_t(h.height) *
                                std::uint64_t(h.channels) * bytes_per_value(h);
  if (decoded > std::uint64_t(input_bytes) * max_expansion + expansion_slack)
    throw bad_input("{} header: {} x {} x {} channels ({} bytes decoded) is more than {} "
                    "bytes of compressed data can hold",
                    what, h.width, h.height, h.channels, decoded, input_bytes);
}

}  // namespace fest::formats::image_detail
