// PGM/PPM (P2, P3, P5, P6) and PAM (P7) pixels, both directions, written here rather
// than with OpenCV because OpenCV 4.6 gets the family wrong in ways that lose data:
//  * its PxM reader rescales ASCII samples to 0..255 when maxval is not 255 but keeps
//    raw samples as they are, so the same image reads differently in P2 and P5;
//  * its PAM writer produces 16-bit and 4-channel files its own reader refuses
//    ("Can't determine selected_fmt"), and it cannot write 2 channels at all.
// Samples are kept as stored (maxval only picks 8 or 16 bits) and must not exceed it.
// Rows are top to bottom, samples R,G,B(,A) -- fest's in-memory order already.
#include <cstdint>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {
namespace {

const char* family_name(const NetpbmLayout& layout) {
  if (layout.magic == '7') return "PAM";
  return layout.header.channels == 3 ? "PPM" : "PGM";
}

template <typename Sample>
void read_raw(std::string_view data, const NetpbmLayout& layout, cv::Mat& out) {
  const std::size_t per_row = std::size_t(out.cols) * out.channels();
  const unsigned maxval = layout.maxval;
  for (int y = 0; y < out.rows; ++y) {
    Sample* row = out.ptr<Sample>(y);
    for (std::size_t i = 0; i < per_row; ++i) {
      const std::size_t at = (std::size_t(y) * per_row + i) * sizeof(Sample);
      unsigned v = std::uint8_t(data[at]);
      if (sizeof(Sample) == 2) v = (v << 8) | std::uint8_t(data[at + 1]);  // big-endian
      if (v > maxval)
        throw bad_input("{} data: sample {} exceeds maxval {} at pixel ({},{})", family_name(layout), v, maxval,
                        i / out.channels(), y);
      row[i] = static_cast<Sample>(v);
    }
  }
}

template <typename Sample>
void read_ascii(std::string_view data, const NetpbmLayout& layout, cv::Mat& out) {
  const std::size_t per_row = std::size_t(out.cols) * out.channels();
  std::size_t pos = 0;
  for (int y = 0; y < out.rows; ++y) {
    Sample* row = out.ptr<Sample>(y);
    for (std::size_t i = 0; i < per_row; ++i) {
      // Whitespace, and (leniently, as Netpbm's own readers are) comments.
      while (pos < data.size()) {
        const char ch = data[pos];
        if (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t' || ch == '\v' || ch == '\f') {
          ++pos;
        } else if (ch == '#') {
          while (pos < data.size() && data[pos] != '\n' && data[pos] != '\r') ++pos;
        } else {
          break;
        }
      }
      if (pos == data.size())
        throw bad_input("{} data: truncated, pixel ({},{}) is missing", family_name(layout), i / out.channels(), y);
      unsigned v = 0;
      const std::size_t start = pos;
      while (pos < data.size() && data[pos] >= '0' && data[pos] <= '9') {
        v = v * 10 + unsigned(data[pos] - '0');
        if (v > layout.maxval)
          throw bad_input("{} data: sample at byte {} exceeds maxval {}", family_name(layout),
                          layout.data_offset + start, layout.maxval);
        ++pos;
      }
      if (pos == start)
        throw bad_input("{} data: byte {} is not a decimal sample", family_name(layout), layout.data_offset + pos);
      row[i] = static_cast<Sample>(v);
    }
  }
}

template <typename Sample>
void append_samples(std::string& out, const cv::Mat& pixels, bool ascii) {
  const std::size_t per_row = std::size_t(pixels.cols) * pixels.channels();
  if (!ascii) {  // raw: rows copied in place (16-bit samples big-endian)
    std::size_t at = out.size();
    out.resize(at + per_row * sizeof(Sample) * std::size_t(pixels.rows));
    for (int y = 0; y < pixels.rows; ++y, at += per_row * sizeof(Sample)) {
      const Sample* row = pixels.ptr<Sample>(y);
      if (sizeof(Sample) == 1) {
        std::memcpy(&out[at], row, per_row);
        continue;
      }
      for (std::size_t i = 0; i < per_row; ++i) {
        out[at + 2 * i] = static_cast<char>(unsigned(row[i]) >> 8);
        out[at + 2 * i + 1] = static_cast<char>(unsigned(row[i]) & 0xff);
      }
    }
    return;
  }
  for (int y = 0; y < pixels.rows; ++y) {
    const Sample* row = pixels.ptr<Sample>(y);
    std::size_t line = 0;
    for (std::size_t i = 0; i < per_row; ++i) {
      const unsigned v = row[i];
      if (ascii) {
        // Plain Netpbm lines should stay under 70 characters.
        const std::string text = fmt::format("{}", v);
        if (line > 0 && line + text.size() + 1 > 70) {
          out += '\n';
          line = 0;
        } else if (line > 0) {
          out += ' ';
          ++line;
        }
        out += text;
        line += text.size();
      } else if (sizeof(Sample) == 2) {
        out += static_cast<char>(v >> 8);
        out += static_cast<char>(v & 0xff);
      } else {
        out += static_cast<char>(v);
      }
    }
    if (ascii) out += '\n';
  }
}

std::string with_samples(std::string header, const cv::Mat& pixels, bool ascii) {
  header.reserve(header.size() + pixels.total() * pixels.elemSize() * (ascii ? 4 : 1));
  if (pixels.depth() == CV_16U) append_samples<std::uint16_t>(header, pixels, ascii);
  else append_samples<std::uint8_t>(header, pixels, ascii);
  return header;
}

unsigned maxval_of(const cv::Mat& pixels) { return pixels.depth() == CV_16U ? 65535u : 255u; }

}  // namespace

cv::Mat decode_netpbm(std::string_view bytes, const NetpbmLayout& layout) {
  const ImageHeader& h = layout.header;
  cv::Mat out(h.height, h.width, CV_MAKETYPE(h.bits == 16 ? CV_16U : CV_8U, h.channels));
  const std::string_view data = bytes.substr(layout.data_offset);
  if (layout.ascii) {
    if (h.bits == 16) read_ascii<std::uint16_t>(data, layout, out);
    else read_ascii<std::uint8_t>(data, layout, out);
  } else {
    if (h.bits == 16) read_raw<std::uint16_t>(data, layout, out);
    else read_raw<std::uint8_t>(data, layout, out);
  }
  return out;
}

std::string encode_pnm(const cv::Mat& pixels, bool ascii) {
  const char magic = pixels.channels() == 3 ? (ascii ? '3' : '6') : (ascii ? '2' : '5');
  return with_samples(fmt::format("P{}\n{} {}\n{}\n", magic, pixels.cols, pixels.rows, maxval_of(pixels)), pixels,
                      ascii);
}

std::string encode_pam(const cv::Mat& pixels) {
  static constexpr const char* tuple_types[] = {"GRAYSCALE", "GRAYSCALE_ALPHA", "RGB", "RGB_ALPHA"};
  return with_samples(fmt::format("P7\nWIDTH {}\nHEIGHT {}\nDEPTH {}\nMAXVAL {}\nTUPLTYPE {}\nENDHDR\n", pixels.cols,
                                  pixels.rows, pixels.channels(), maxval_of(pixels),
                                  tuple_types[pixels.channels() - 1]),
                      pixels, false);
}

}  // namespace fest::formats::image_detail
