#include "terrainlod/tlp_archive.hpp"

#include "core/error.hpp"
#include "core/little_endian.hpp"

namespace fest::terrainlod {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'L', 'P'};
constexpr std::uint8_t kVersion = 1;        // no nodata section
constexpr std::uint8_t kVersionNodata = 2;  // a nodata section after the index
constexpr std::size_t kEntryBytes = 1 + 4 + 4 + 8 + 4 + 8 + 4;

using little_endian::get_le;
using little_endian::put_le;

}  // namespace

bool looks_like_tlp(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == std::string_view(kMagic, 4); }

std::string encode_tlp_head(std::string_view manifest_json, const std::vector<TlpEntry>& tiles, std::string_view nodata) {
  std::string out(kMagic, 4);
  put_le<std::uint8_t>(out, nodata.empty() ? kVersion : kVersionNodata);
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(manifest_json.size()));
  out += manifest_json;
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(tiles.size()));
  std::uint64_t offset = out.size() + kEntryBytes * tiles.size() + (nodata.empty() ? 0 : 4 + nodata.size());
  for (const auto& t : tiles) {
    put_le<std::uint8_t>(out, static_cast<std::uint8_t>(t.id.level));
    put_le<std::uint32_t>(out, static_cast<std::uint32_t>(t.id.x));
    put_le<std::uint32_t>(out, static_cast<std::uint32_t>(t.id.y));
    put_le<std::uint64_t>(out, offset);
    put_le<std::uint32_t>(out, t.length);
    offset += t.length;
    put_le<std::uint64_t>(out, t.texture_length ? offset : 0);
    put_le<std::uint32_t>(out, t.texture_length);
    offset += t.texture_length;
  }
  if (!nodata.empty()) {
    put_le<std::uint32_t>(out, static_cast<std::uint32_t>(nodata.size()));
    out += nodata;
  }
  return out;
}

TlpHead decode_tlp_head(std::string_view s) {
  if (!looks_like_tlp(s)) throw bad_input("not a terrainlod pyramid (bad magic)");
  if (s.size() < 9) throw bad_input("pyramid is truncated: {} bytes", s.size());
  const int version = get_le<std::uint8_t>(s, 4);
  if (version != kVersion && version != kVersionNodata)
    throw bad_input("pyramid version {} is not supported (this reads versions {} and {})", version, kVersion, kVersionNodata);
  const std::size_t mlen = get_le<std::uint32_t>(s, 5);
  if (s.size() < 9 + mlen + 4) throw bad_input("pyramid is truncated in its manifest");
  return {s.substr(9, mlen), 9 + mlen, version};
}

std::vector<TlpEntry> decode_tlp_index(std::string_view s, std::size_t at) {
  if (at > s.size() || s.size() - at < 4) throw bad_input("pyramid is truncated in its tile index");
  const std::size_t count = get_le<std::uint32_t>(s, at);
  at += 4;
  if (s.size() < at + count * kEntryBytes) throw bad_input("pyramid is truncated in its tile index");
  std::vector<TlpEntry> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i, at += kEntryBytes) {
    TlpEntry e;
    e.id = {get_le<std::uint8_t>(s, at), static_cast<int>(get_le<std::uint32_t>(s, at + 1)),
            static_cast<int>(get_le<std::uint32_t>(s, at + 5))};
    e.offset = get_le<std::uint64_t>(s, at + 9);
    e.length = get_le<std::uint32_t>(s, at + 17);
    e.texture_offset = get_le<std::uint64_t>(s, at + 21);
    e.texture_length = get_le<std::uint32_t>(s, at + 29);
    out.push_back(e);
  }
  return out;
}

std::string_view decode_tlp_nodata(std::string_view s, const TlpHead& head) {
  if (head.version != kVersionNodata) return {};
  std::size_t at = head.index_at;
  if (at > s.size() || s.size() - at < 4) throw bad_input("pyramid is truncated in its tile index");
  const std::size_t count = get_le<std::uint32_t>(s, at);
  at += 4;
  if ((s.size() - at) / kEntryBytes < count || s.size() - at - count * kEntryBytes < 4)
    throw bad_input("pyramid is truncated before its nodata section");
  at += count * kEntryBytes;
  const std::size_t len = get_le<std::uint32_t>(s, at);
  at += 4;
  if (len == 0 || s.size() - at < len) throw bad_input("pyramid's nodata section is truncated or empty");
  return s.substr(at, len);
}

}  // namespace fest::terrainlod
