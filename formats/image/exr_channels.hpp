#pragma once
// What the EXR header parser hands to the EXR decoder.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/image/image_io.hpp"

namespace fest::formats::image_detail {

struct ExrChannel {
  std::string name;
  int pixel_type = 0;  // 0 uint, 1 half, 2 float
};

struct ExrLayout {
  ImageHeader header;
  std::vector<ExrChannel> channels;      // in memory order: R,G,B(,A) or Y(,A)
  std::array<std::int32_t, 4> data_window{};  // xMin, yMin, xMax, yMax
  int compression = 0;
  bool tiled = false;
  std::uint32_t tile_width = 0, tile_height = 0;  // tiled files only
  std::size_t header_end = 0;
};

ExrLayout read_exr_layout(std::string_view bytes);
int exr_lines_per_chunk(int compression);
std::vector<ExrChannel> order_channels(const std::vector<ExrChannel>& found);

}  // namespace fest::formats::image_detail
