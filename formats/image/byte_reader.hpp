#pragma once
// Bounds-checked reads of fixed-size integers from untrusted bytes.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fest::formats::image_detail {

inline bool fits(std::string_view bytes, std::uint64_t offset, std::uint64_t length) {
  return offset <= bytes.size() && length <= bytes.size() - offset;
}

inline std::uint32_t load_u32_be(std::string_view b, std::size_t at) {
  return (std::uint32_t(std::uint8_t(b[at])) << 24) | (std::uint32_t(std::uint8_t(b[at + 1])) << 16) |
         (std::uint32_t(std::uint8_t(b[at + 2])) << 8) | std::uint32_t(std::uint8_t(b[at + 3]));
}
inline std::uint32_t load_u32_le(std::string_view b, std::size_t at) {
  return (std::uint32_t(std::uint8_t(b[at + 3])) << 24) | (std::uint32_t(std::uint8_t(b[at + 2])) << 16) |
         (std::uint32_t(std::uint8_t(b[at + 1])) << 8) | std::uint32_t(std::uint8_t(b[at]));
}
inline std::uint16_t load_u16_be(std::string_view b, std::size_t at) {
  return std::uint16_t((std::uint8_t(b[at]) << 8) | std::uint8_t(b[at + 1]));
}
inline std::uint16_t load_u16_le(std::string_view b, std::size_t at) {
  return std::uint16_t((std::uint8_t(b[at + 1]) << 8) | std::uint8_t(b[at]));
}

}  // namespace fest::formats::image_detail
