#pragma once
// gzip (RFC 1952) and zlib (RFC 1950) streams in memory, with a bound on the
// decompressed size so a small bomb cannot exhaust memory.

#include <cstdint>
#include <string>
#include <string_view>

namespace fest::formats {

bool is_gzip(std::string_view bytes) noexcept;  // 1f 8b

// Decompresses gzip or zlib data (auto-detected by zlib); concatenated gzip members
// are all read. Throws Status::bad_input when the data is corrupt or truncated, or
// decompresses to more than `limit` bytes (default: fest::max_input_bytes()).
std::string gunzip(std::string_view compressed, std::uint64_t limit = 0);

// Like gunzip, but stops successfully after `expected` bytes and throws when fewer
// are available: for formats that state their data size (NRRD, MetaImage).
std::string inflate_exact(std::string_view compressed, std::uint64_t expected);

// gzip (with header) at the given level, or raw zlib when `zlib_header` is true.
std::string gzip(std::string_view data, int level = 6, bool zlib_header = false);

}  // namespace fest::formats
