#pragma once
// CRC-32 (ISO-HDLC, the one of gzip and PNG) of a byte string, by zlib: the checksum of
// .ebm files and of .vw chunks from format version 5. Header-only so that lib/core itself
// needs no zlib; a library that includes this links ZLIB::ZLIB.

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <string_view>

namespace fest {

inline std::uint32_t crc32_of(std::string_view bytes) noexcept {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes uInt lengths: feed in pieces.
  std::size_t pos = 0;
  while (pos < bytes.size()) {
    const std::size_t n = std::min<std::size_t>(bytes.size() - pos, std::size_t{1} << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + pos), static_cast<uInt>(n));
    pos += n;
  }
  return static_cast<std::uint32_t>(crc);
}

}  // namespace fest
