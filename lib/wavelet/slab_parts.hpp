#pragma once
// Every coded slab (adaptive, static and packed; docs/volwave.md §4, fest-vw(5)) starts
// with N varint lengths, then the N parts they measure, then the rest of its bytes (the
// raw bits). One writer and one reader of that layout for the three coders.

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "core/little_endian.hpp"

namespace fest::wavelet {

// Appends the lengths of `parts`, the parts, then `rest` (whose length the reader infers).
inline void append_slab_parts(std::string& out, std::initializer_list<std::string_view> parts, std::string_view rest) {
  for (std::string_view p : parts) little_endian::put_varint(out, p.size());
  for (std::string_view p : parts) out += p;
  out += rest;
}

// The N parts and the rest, or nothing when a varint is longer than 64 bits or runs out,
// or a part runs past the bytes (the caller names the corrupt band and slab).
template <std::size_t N>
std::optional<std::array<std::string_view, N + 1>> slab_parts(std::string_view bytes) noexcept {
  std::size_t pos = 0;
  std::array<std::uint64_t, N> length{};
  for (std::uint64_t& v : length) {
    for (int shift = 0;; shift += 7) {
      if (shift >= 64 || pos >= bytes.size()) return std::nullopt;
      const auto byte = static_cast<std::uint8_t>(bytes[pos++]);
      v |= static_cast<std::uint64_t>(byte & 0x7F) << shift;
      if (!(byte & 0x80)) break;
    }
  }
  std::array<std::string_view, N + 1> parts;
  for (std::size_t i = 0; i < N; ++i) {
    if (length[i] > bytes.size() - pos) return std::nullopt;
    parts[i] = bytes.substr(pos, static_cast<std::size_t>(length[i]));
    pos += static_cast<std::size_t>(length[i]);
  }
  parts[N] = bytes.substr(pos);
  return parts;
}

}  // namespace fest::wavelet
