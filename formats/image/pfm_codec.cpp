// PFM pixels. Reading is fest's own because OpenCV 4.6 divides every sample by the
// magnitude of the header's scale (a file with scale 2.5 reads as 0.4 x its values);
// the magnitude has no agreed meaning, its sign only gives the byte order, so samples
// are kept as stored, as most PFM readers do. Writing gives what OpenCV's writer gave:
// "PF\n" or "Pf\n", "W H\n", "-1\n" (little-endian), rows bottom to top.
#include <cstdint>
#include <cstring>
#include <utility>
#include <string>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {

cv::Mat decode_pfm(std::string_view bytes, const NetpbmLayout& layout) {
  const ImageHeader& h = layout.header;
  cv::Mat out(h.height, h.width, CV_MAKETYPE(CV_32F, h.channels));
  const std::size_t row_bytes = std::size_t(h.width) * std::size_t(h.channels) * 4;
  // read_netpbm_layout checked the data holds height * row_bytes.
  const char* data = bytes.data() + layout.data_offset;
  const std::uint16_t probe = 1;
  const bool host_little = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
  const bool swap = layout.big_endian == host_little;
  for (int y = 0; y < h.height; ++y) {
    // The file's first row is the bottom of the image.
    char* row = out.ptr<char>(h.height - 1 - y);
    std::memcpy(row, data + std::size_t(y) * row_bytes, row_bytes);
    if (swap)
      for (std::size_t i = 0; i < row_bytes; i += 4) {
        std::swap(row[i], row[i + 3]);
        std::swap(row[i + 1], row[i + 2]);
      }
  }
  return out;
}

std::string encode_pfm(const cv::Mat& pixels) {
  const std::size_t row_bytes = pixels.cols * pixels.elemSize();
  std::string out = (pixels.channels() == 3 ? "PF\n" : "Pf\n") + std::to_string(pixels.cols) + " " +
                    std::to_string(pixels.rows) + "\n-1\n";
  const std::size_t header = out.size();
  out.resize(header + row_bytes * std::size_t(pixels.rows));
  const std::uint16_t probe = 1;
  const bool host_little = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
  for (int y = 0; y < pixels.rows; ++y) {
    char* row = out.data() + header + std::size_t(pixels.rows - 1 - y) * row_bytes;
    std::memcpy(row, pixels.ptr<char>(y), row_bytes);
    if (!host_little)
      for (std::size_t i = 0; i < row_bytes; i += 4) {
        std::swap(row[i], row[i + 3]);
        std::swap(row[i + 1], row[i + 2]);
      }
  }
  return out;
}

}  // namespace fest::formats::image_detail
