// Header parsing for PGM/PPM (P2, P3, P5, P6), PAM (P7) and PFM (PF, Pf).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/image/image_headers.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Walks a Netpbm header: tokens separated by whitespace, '#' comments to end of line.
class HeaderCursor {
 public:
  HeaderCursor(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}

  void skip_space_and_comments() {
    while (pos_ < bytes_.size()) {
      if (is_space(bytes_[pos_])) {
        ++pos_;
      } else if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else {
        return;
      }
    }
  }

  std::string_view token() {
    skip_space_and_comments();
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_]) && bytes_[pos_] != '#') ++pos_;
    if (start == pos_) throw bad_input("{} header: truncated at byte {}", what_, start);
    return bytes_.substr(start, pos_ - start);
  }

  // A non-negative decimal integer; `name` says which field for the message.
  std::int64_t integer(const char* name) {
    const std::size_t at = pos_;
    std::string_view t = token();
    std::size_t i = (t[0] == '-' || t[0] == '+') ? 1 : 0;
    if (i == t.size()) throw bad_input("{} header: {} '{}' is not a number (byte {})", what_, name, fest::quoted_bytes(t), at);
    std::int64_t value = 0;
    for (; i < t.size(); ++i) {
      if (t[i] < '0' || t[i] > '9')
        throw bad_input("{} header: {} '{}' is not a number (byte {})", what_, name, fest::quoted_bytes(t), at);
      if (value > (std::int64_t{1} << 40))
        throw bad_input("{} header: {} '{}' is too large", what_, name, fest::quoted_bytes(t));
      value = value * 10 + (t[i] - '0');
    }
    return t[0] == '-' ? -value : value;
  }

  // The header ends with exactly one whitespace character before raw data.
  void single_whitespace() {
    if (pos_ >= bytes_.size() || !is_space(bytes_[pos_]))
      throw bad_input("{} header: no whitespace after the last header field (byte {})", what_, pos_);
    ++pos_;
  }

  std::size_t position() const { return pos_; }
  void advance(std::size_t n) { pos_ += n; }

 private:
  std::string_view bytes_;
  const char* what_;
  std::size_t pos_ = 0;
};

int checked_int(std::int64_t v, const char* what, const char* name) {
  if (v <= 0 || v > (std::int64_t{1} << 30))
    throw bad_input("{} header: {} {} is out of range", what, name, v);
  return static_cast<int>(v);
}

unsigned checked_maxval(std::int64_t v, const char* what) {
  if (v <= 0 || v > 65535) throw bad_input("{} header: maxval {} is outside 1..65535", what, v);
  return static_cast<unsigned>(v);
}

int channels_of_tuple_type(std::string_view t) {
  if (t == "GRAYSCALE" || t == "BLACKANDWHITE") return 1;
  if (t == "GRAYSCALE_ALPHA" || t == "BLACKANDWHITE_ALPHA") return 2;
  if (t == "RGB") return 3;
  if (t == "RGB_ALPHA") return 4;
  return 0;
}

// P7: "WIDTH w", "HEIGHT h", "DEPTH d", "MAXVAL m", optional "TUPLTYPE t", "ENDHDR".
void read_pam_fields(HeaderCursor& cursor, NetpbmLayout& layout) {
  const char* what = "PAM";
  std::int64_t width = -1, height = -1, depth = -1, maxval = -1;
  std::string tuple_type;
  for (;;) {
    const std::size_t at = cursor.position();
    std::string_view key = cursor.token();
    if (key == "ENDHDR") break;
    if (key == "WIDTH") width = cursor.integer("WIDTH");
    else if (key == "HEIGHT") height = cursor.integer("HEIGHT");
    else if (key == "DEPTH") depth = cursor.integer("DEPTH");
    else if (key == "MAXVAL") maxval = cursor.integer("MAXVAL");
    else if (key == "TUPLTYPE") tuple_type = std::string(cursor.token());
    else throw bad_input("PAM header: unknown field '{}' at byte {}", fest::quoted_bytes(key, 32), at);
  }
  // ENDHDR is followed by one newline, then the raster.
  cursor.single_whitespace();
  if (width < 0 || height < 0 || depth < 0 || maxval < 0)
    throw bad_input("PAM header: WIDTH, HEIGHT, DEPTH and MAXVAL are all required");
  layout.header.width = checked_int(width, what, "WIDTH");
  layout.header.height = checked_int(height, what, "HEIGHT");
  if (depth < 1 || depth > 4) throw bad_input("PAM header: DEPTH {} (1 to 4 supported)", depth);
  layout.header.channels = static_cast<int>(depth);
  layout.maxval = checked_maxval(maxval, what);
  if (!tuple_type.empty()) {
    const int expected = channels_of_tuple_type(tuple_type);
    if (expected == 0) throw bad_input("PAM header: unknown TUPLTYPE '{}'", fest::quoted_bytes(tuple_type, 32));
    if (expected != depth)
      throw bad_input("PAM header: TUPLTYPE {} needs DEPTH {}, not {}", tuple_type, expected, depth);
  }
}

void read_pfm_fields(HeaderCursor& cursor, NetpbmLayout& layout) {
  const char* what = "PFM";
  layout.header.width = checked_int(cursor.integer("width"), what, "width");
  layout.header.height = checked_int(cursor.integer("height"), what, "height");
  const std::size_t at = cursor.position();
  std::string scale_text(cursor.token().substr(0, 64));
  char* end = nullptr;
  const double scale = std::strtod(scale_text.c_str(), &end);
  if (end != scale_text.c_str() + scale_text.size() || !std::isfinite(scale) || scale == 0.0)
    throw bad_input("PFM header: scale '{}' at byte {} is not a finite non-zero number", fest::quoted_bytes(scale_text), at);
  // The sign of the scale is the byte order: negative means little-endian.
  layout.big_endian = scale > 0;
  cursor.single_whitespace();
  layout.header.channels = layout.magic == 'F' ? 3 : 1;
  layout.header.bits = 32;
  layout.header.is_float = true;
}

}  // namespace

NetpbmLayout read_netpbm_layout(std::string_view bytes, bool pfm) { return read_netpbm_layout(bytes, pfm, bytes.size()); }

NetpbmLayout read_netpbm_layout(std::string_view bytes, bool pfm, std::uint64_t total_size) {
  const char* what = pfm ? "PFM" : "PNM";
  if (bytes.size() < 2 || bytes[0] != 'P')
    throw bad_input("{} header: missing 'P' magic at byte 0", what);
  NetpbmLayout layout;
  layout.magic = bytes[1];
  const bool magic_ok = pfm ? (layout.magic == 'F' || layout.magic == 'f')
                            : (layout.magic == '2' || layout.magic == '3' || layout.magic == '5' ||
                               layout.magic == '6' || layout.magic == '7');
  if (!magic_ok) {
    if (!pfm && (layout.magic == '1' || layout.magic == '4'))
      throw bad_input("PNM header: P{} bitmaps (PBM) are not supported", layout.magic);
    throw bad_input("{} header: unknown magic 'P{}'", what, layout.magic);
  }
  HeaderCursor cursor(bytes, what);
  cursor.advance(2);
  if (cursor.position() >= bytes.size() || !is_space(bytes[2]))
    throw bad_input("{} header: no whitespace after the magic", what);

  if (pfm) {
    read_pfm_fields(cursor, layout);
  } else if (layout.magic == '7') {
    read_pam_fields(cursor, layout);
  } else {
    layout.header.width = checked_int(cursor.integer("width"), what, "width");
    layout.header.height = checked_int(cursor.integer("height"), what, "height");
    layout.maxval = checked_maxval(cursor.integer("maxval"), what);
    cursor.single_whitespace();
    layout.header.channels = (layout.magic == '3' || layout.magic == '6') ? 3 : 1;
    layout.ascii = layout.magic == '2' || layout.magic == '3';
  }
  if (!pfm) {
    layout.header.bits = layout.maxval > 255 ? 16 : 8;
    layout.header.is_float = false;
  }
  check_dimensions(layout.header, what);
  layout.data_offset = cursor.position();

  // Data size, checked before anything is allocated.
  const std::uint64_t values = std::uint64_t(layout.header.width) * std::uint64_t(layout.header.height) *
                               std::uint64_t(layout.header.channels);
  const std::uint64_t available = total_size - layout.data_offset;
  if (layout.ascii) {
    // Each sample needs at least one digit and all but the last a separator.
    if (available < 2 * values - 1)
      throw bad_input("{} data: {} samples cannot fit in the {} bytes after the header", what, values,
                      available);
  } else {
    const std::uint64_t needed = values * bytes_per_value(layout.header);
    if (available < needed)
      throw bad_input("{} data: truncated, {} bytes of pixels expected after the header, {} present",
                      what, needed, available);
  }
  return layout;
}

}  // namespace fest::formats::image_detail
