#include "formats/gzip.hpp"

#include <zlib.h>

#include <limits>

#include "core/error.hpp"
#include "core/file_io.hpp"

namespace fest::formats {

namespace {

// Runs inflate over `in` until the stream ends, `stop_after` bytes are out, or an
// error. windowBits 15+32 lets zlib accept both gzip and zlib headers.
std::string inflate_bounded(std::string_view in, std::uint64_t limit, std::uint64_t stop_after) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) throw bad_input("cannot initialise zlib");
  std::string out;
  // Grow in steps; never reserve from a size the data claims.
  char chunk[1 << 16];
  const Bytef* next = reinterpret_cast<const Bytef*>(in.data());
  std::size_t left = in.size();
  int ret = Z_OK;
  for (;;) {
    if (zs.avail_in == 0 && left > 0) {
      const std::size_t step = std::min<std::size_t>(left, std::numeric_limits<uInt>::max());
      zs.next_in = const_cast<Bytef*>(next);
      zs.avail_in = static_cast<uInt>(step);
      next += step;
      left -= step;
    }
    zs.next_out = reinterpret_cast<Bytef*>(chunk);
    zs.avail_out = sizeof chunk;
    ret = inflate(&zs, Z_NO_FLUSH);
    const std::size_t produced = sizeof chunk - zs.avail_out;
    if (out.size() + produced > limit) {
      inflateEnd(&zs);
      throw bad_input("compressed data expands beyond {} bytes", limit);
    }
    out.append(chunk, produced);
    if (stop_after > 0 && out.size() >= stop_after) break;
    if (ret == Z_STREAM_END) {
      // Concatenated gzip members (as `cat a.gz b.gz` makes) form one stream.
      if (zs.avail_in + left > 0 && stop_after == 0) {
        if (inflateReset(&zs) != Z_OK) break;
        continue;
      }
      break;
    }
    if (ret == Z_BUF_ERROR && zs.avail_in == 0 && left == 0) {
      inflateEnd(&zs);
      throw bad_input("compressed data is truncated");
    }
    if (ret != Z_OK && ret != Z_BUF_ERROR) {
      std::string why = zs.msg ? zs.msg : "corrupt data";
      inflateEnd(&zs);
      throw bad_input("compressed data is corrupt: {}", why);
    }
  }
  inflateEnd(&zs);
  return out;
}

}  // namespace

bool is_gzip(std::string_view bytes) noexcept {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gunzip(std::string_view compressed, std::uint64_t limit) {
  if (limit == 0) limit = max_input_bytes();
  return inflate_bounded(compressed, limit, 0);
}

std::string inflate_exact(std::string_view compressed, std::uint64_t expected) {
  if (expected == 0) return {};
  std::string out = inflate_bounded(compressed, expected + (1 << 16), expected);
  if (out.size() < expected)
    throw bad_input("compressed data holds {} bytes, {} expected", out.size(), expected);
  out.resize(static_cast<std::size_t>(expected));
  return out;
}

std::string gzip(std::string_view data, int level, bool zlib_header) {
  z_stream zs{};
  // windowBits 15 = zlib wrapper, 15+16 = gzip wrapper; memLevel 8 is zlib's default.
  if (deflateInit2(&zs, level, Z_DEFLATED, zlib_header ? 15 : 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw make_error(Status::failure, "cannot initialise zlib");
  std::string out;
  out.resize(deflateBound(&zs, static_cast<uLong>(data.size())) + 64);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  if (data.size() > std::numeric_limits<uInt>::max()) {
    deflateEnd(&zs);
    throw make_error(Status::failure, "data too large to compress in one piece");
  }
  int ret = deflate(&zs, Z_FINISH);
  deflateEnd(&zs);
  if (ret != Z_STREAM_END) throw make_error(Status::failure, "zlib deflate failed");
  out.resize(zs.total_out);
  return out;
}

}  // namespace fest::formats
