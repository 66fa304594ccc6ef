#include "formats/volume/orientation_stated.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>

namespace fest::formats {

namespace {

// An integer of `size` bytes at `offset`, little- or big-endian.
std::int64_t integer_at(std::string_view b, std::size_t offset, std::size_t size, bool big) {
  if (offset + size > b.size()) return 0;
  std::uint64_t u = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const auto byte = static_cast<unsigned char>(b[big ? offset + i : offset + size - 1 - i]);
    u = (u << 8) | byte;
  }
  // Sign-extend.
  if (size < 8 && (u >> (8 * size - 1)) & 1u) u |= ~std::uint64_t{0} << (8 * size);
  return static_cast<std::int64_t>(u);
}

bool nifti_states(std::string_view b) {
  for (bool big : {false, true}) {
    const std::int64_t size = integer_at(b, 0, 4, big);
    if (size == 348) return integer_at(b, 252, 2, big) > 0 || integer_at(b, 254, 2, big) > 0;
    if (size == 540) return integer_at(b, 344, 4, big) > 0 || integer_at(b, 348, 4, big) > 0;
  }
  return false;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Calls f(key, value) for each header line "key<sep>value": true when f returns 1 for
// one; false at a line for which it returns -1 (the end of a MetaImage header), an empty
// line (NRRD's end of header) or after 64 KiB.
template <class F>
bool any_header_line(std::string_view b, char sep, F f) {
  b = b.substr(0, std::min<std::size_t>(b.size(), 65536));
  std::size_t pos = 0;
  while (pos < b.size()) {
    std::size_t end = b.find('\n', pos);
    if (end == std::string_view::npos) end = b.size();
    const std::string_view line = trim(b.substr(pos, end - pos));
    pos = end + 1;
    if (line.empty()) break;
    const std::size_t s = line.find(sep);
    if (s == std::string_view::npos) continue;
    const int answer = f(lower(trim(line.substr(0, s))), trim(line.substr(s + 1)));
    if (answer != 0) return answer > 0;
  }
  return false;
}

}  // namespace

bool volume_orientation_stated(const Input& in) noexcept {
  try {
    const std::string_view b = in.bytes;
    switch (in.format) {
      case Format::nifti:
      case Format::nifti2:
      case Format::nifti_pair: return nifti_states(b);
      case Format::mgh: return integer_at(b, 28, 2, true) != 0;
      case Format::nrrd:
        return any_header_line(b, ':', [](const std::string& key, std::string_view) { return key == "space directions" ? 1 : 0; });
      case Format::mha:
        return any_header_line(b, '=', [](const std::string& key, std::string_view value) {
          if (key == "transformmatrix" || key == "orientation" || key == "rotation") return 1;
          if (key == "anatomicalorientation" && value.find('?') == std::string_view::npos) return 1;
          return key == "elementdatafile" ? -1 : 0;
        });
      default: return false;
    }
  } catch (...) {
    return false;
  }
}

}  // namespace fest::formats
