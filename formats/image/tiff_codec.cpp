// TIFF through libtiff directly, on in-memory streams. Reading follows what OpenCV 4.6
// did, so pixels are unchanged: 8-bit images through libtiff's RGBA interface (which
// handles palette, YCbCr, min-is-white, CMYK) cut back to the header's channel count;
// 16-bit and float samples as stored. Writing follows OpenCV's writer too: one
// contiguous plane, strips of about 8 KiB, LZW with the horizontal predictor for
// integers, no compression for float.
//
// libtiff's messages go to per-file handlers (TIFFOpenOptions, libtiff >= 4.5): the
// last error becomes the bad-input message; warnings (unknown tags) are dropped.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <tiffio.h>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {
namespace {

struct TiffStream {
  std::string_view in;   // reading
  std::string* out = nullptr;  // writing
  std::uint64_t at = 0;
  char message[512] = {};
};

// The module (the name given to TIFFClientOpenExt, or a codec's name) adds nothing for
// the user: the message alone, on one line.
int on_error(TIFF*, void* user, const char*, const char* format, va_list args) {
  auto* s = static_cast<TiffStream*>(user);
  std::vsnprintf(s->message, sizeof s->message, format, args);
  for (char* c = s->message; *c; ++c)
    if (*c == '\n' || *c == '\r') *c = ' ';
  return 1;  // handled: libtiff's global handler (stderr) is not called
}

int on_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

tmsize_t read_proc(thandle_t h, void* buf, tmsize_t n) {
  auto* s = static_cast<TiffStream*>(h);
  if (s->out) return 0;
  const std::uint64_t left = s->at < s->in.size() ? s->in.size() - s->at : 0;
  const std::uint64_t k = std::min<std::uint64_t>(left, std::uint64_t(n));
  std::memcpy(buf, s->in.data() + s->at, k);
  s->at += k;
  return tmsize_t(k);
}

tmsize_t write_proc(thandle_t h, void* buf, tmsize_t n) {
  auto* s = static_cast<TiffStream*>(h);
  if (!s->out) return 0;
  if (s->out->size() < s->at + std::uint64_t(n)) s->out->resize(s->at + std::uint64_t(n));
  std::memcpy(s->out->data() + s->at, buf, std::size_t(n));
  s->at += std::uint64_t(n);
  return n;
}

std::uint64_t size_of(const TiffStream& s) { return s.out ? s.out->size() : s.in.size(); }

toff_t seek_proc(thandle_t h, toff_t off, int whence) {
  auto* s = static_cast<TiffStream*>(h);
  std::uint64_t base = whence == SEEK_CUR ? s->at : whence == SEEK_END ? size_of(*s) : 0;
  s->at = base + off;
  return s->at;
}

int close_proc(thandle_t) { return 0; }
toff_t size_proc(thandle_t h) { return size_of(*static_cast<TiffStream*>(h)); }
int map_proc(thandle_t h, void** base, toff_t* size) {
  auto* s = static_cast<TiffStream*>(h);
  if (s->out) return 0;
  *base = const_cast<char*>(s->in.data());
  *size = s->in.size();
  return 1;
}
void unmap_proc(thandle_t, void*, toff_t) {}

// Opens `stream` for reading ("r") or writing ("w") with fest's message handlers.
TIFF* open(TiffStream& stream, const char* mode) {
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, on_error, &stream);
  TIFFOpenOptionsSetWarningHandlerExtR(options, on_warning, &stream);
  TIFF* tif = TIFFClientOpenExt("TIFF", mode, &stream, read_proc, write_proc, seek_proc, close_proc, size_proc,
                                map_proc, unmap_proc, options);
  TIFFOpenOptionsFree(options);
  return tif;
}

struct TiffCloser {
  TIFF* tif;
  ~TiffCloser() { if (tif) TIFFClose(tif); }
};

[[noreturn]] void fail(const TiffStream& s, const char* what) {
  throw bad_input("TIFF data: {}", s.message[0] ? s.message : what);
}

// 8-bit: libtiff's RGBA raster (A, B, G, R from the high byte down), top row first.
cv::Mat read_8bit(TIFF* tif, const TiffStream& s, int width, int height, int channels) {
  char why[1024] = {};
  if (!TIFFRGBAImageOK(tif, why)) throw bad_input("TIFF data: {}", why);
  std::vector<std::uint32_t> raster(std::size_t(width) * std::size_t(height));
  if (!TIFFReadRGBAImageOriented(tif, std::uint32_t(width), std::uint32_t(height), raster.data(),
                                 ORIENTATION_TOPLEFT, 1))
    fail(s, "corrupt or truncated pixel data");
  cv::Mat pixels(height, width, CV_MAKETYPE(CV_8U, channels));
  for (int y = 0; y < height; ++y) {
    const std::uint32_t* in = raster.data() + std::size_t(y) * std::size_t(width);
    std::uint8_t* out = pixels.ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      const std::uint32_t p = in[x];
      const std::uint8_t r = TIFFGetR(p), g = TIFFGetG(p), b = TIFFGetB(p), a = TIFFGetA(p);
      switch (channels) {
        case 1: *out++ = r; break;  // grey comes back with R = G = B
        case 2: *out++ = r; *out++ = a; break;
        case 3: *out++ = r; *out++ = g; *out++ = b; break;
        default: *out++ = r; *out++ = g; *out++ = b; *out++ = a;
      }
    }
  }
  return pixels;
}

// 16-bit and float: the samples as stored, from strips or tiles, contiguous or planar.
cv::Mat read_samples(TIFF* tif, const TiffStream& s, int width, int height, int channels, int depth) {
  std::uint16_t planar = PLANARCONFIG_CONTIG;
  TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
  cv::Mat pixels(height, width, CV_MAKETYPE(depth, channels));
  const std::size_t value_bytes = pixels.elemSize1();
  const int planes = planar == PLANARCONFIG_SEPARATE ? channels : 1;
  const int per_plane = planar == PLANARCONFIG_SEPARATE ? 1 : channels;
  const std::size_t group = value_bytes * std::size_t(per_plane);  // bytes of one pixel in one plane
  auto put = [&](int plane, int y, int x0, const char* from, int count) {
    char* row = pixels.ptr<char>(y);
    if (planes == 1) {
      std::memcpy(row + std::size_t(x0) * pixels.elemSize(), from, std::size_t(count) * group);
      return;
    }
    for (int x = 0; x < count; ++x)
      std::memcpy(row + (std::size_t(x0 + x) * channels + plane) * value_bytes, from + std::size_t(x) * value_bytes,
                  value_bytes);
  };
  if (TIFFIsTiled(tif)) {
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
    if (tw == 0 || th == 0) throw bad_input("TIFF data: tile size {} x {} is invalid", tw, th);
    std::vector<char> tile(std::size_t(TIFFTileSize(tif)));
    if (tile.size() < std::size_t(tw) * th * group) throw bad_input("TIFF data: tile size does not match the tile");
    for (int plane = 0; plane < planes; ++plane)
      for (std::uint32_t ty = 0; ty < std::uint32_t(height); ty += th)
        for (std::uint32_t tx = 0; tx < std::uint32_t(width); tx += tw) {
          if (TIFFReadTile(tif, tile.data(), tx, ty, 0, std::uint16_t(plane)) < 0)
            fail(s, "corrupt or truncated tile");
          const int count = int(std::min<std::uint32_t>(tw, std::uint32_t(width) - tx));
          for (std::uint32_t r = 0; r < th && ty + r < std::uint32_t(height); ++r)
            put(plane, int(ty + r), int(tx), tile.data() + std::size_t(r) * tw * group, count);
        }
    return pixels;
  }
  std::vector<char> line(std::size_t(TIFFScanlineSize(tif)));
  if (line.size() < std::size_t(width) * group) throw bad_input("TIFF data: scanline size does not match the width");
  for (int plane = 0; plane < planes; ++plane)
    for (int y = 0; y < height; ++y) {
      if (TIFFReadScanline(tif, line.data(), std::uint32_t(y), std::uint16_t(plane)) < 0)
        fail(s, "corrupt or truncated strip");
      put(plane, y, 0, line.data(), width);
    }
  return pixels;
}

}  // namespace

cv::Mat decode_tiff(std::string_view bytes, const ImageHeader& expected) {
  TiffStream stream;
  stream.in = bytes;
  TiffCloser tif{open(stream, "rm")};
  if (!tif.tif) fail(stream, "cannot open the TIFF directory");
  std::uint16_t photometric = PHOTOMETRIC_MINISBLACK;
  TIFFGetFieldDefaulted(tif.tif, TIFFTAG_PHOTOMETRIC, &photometric);
  if (expected.bits == 8) return read_8bit(tif.tif, stream, expected.width, expected.height, expected.channels);
  if (photometric != PHOTOMETRIC_MINISBLACK && photometric != PHOTOMETRIC_RGB)
    throw bad_input("TIFF data: photometric interpretation {} with {}-bit samples is not supported", photometric,
                    expected.bits);
  return read_samples(tif.tif, stream, expected.width, expected.height, expected.channels,
                      expected.is_float ? CV_32F : CV_16U);
}

std::string encode_tiff(const cv::Mat& pixels) {
  const int channels = pixels.channels(), depth = pixels.depth();
  const bool is_float = depth == CV_32F;
  const int bits = depth == CV_8U ? 8 : depth == CV_16U ? 16 : 32;
  std::string out;
  TiffStream stream;
  stream.out = &out;
  TiffCloser tif{open(stream, "w")};
  if (!tif.tif) throw runtime_failure("TIFF writer: {}", stream.message);
  const std::size_t row_bytes = pixels.cols * pixels.elemSize();
  const int rows_per_strip = std::max(1, std::min(pixels.rows, int((1 << 13) / row_bytes)));
  const std::uint16_t compression = is_float ? COMPRESSION_NONE : COMPRESSION_LZW;
  bool ok = TIFFSetField(tif.tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(pixels.cols)) &&
            TIFFSetField(tif.tif, TIFFTAG_IMAGELENGTH, std::uint32_t(pixels.rows)) &&
            TIFFSetField(tif.tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(bits)) &&
            TIFFSetField(tif.tif, TIFFTAG_COMPRESSION, compression) &&
            TIFFSetField(tif.tif, TIFFTAG_PHOTOMETRIC, channels > 2 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK) &&
            TIFFSetField(tif.tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(channels)) &&
            TIFFSetField(tif.tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
            TIFFSetField(tif.tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(rows_per_strip)) &&
            TIFFSetField(tif.tif, TIFFTAG_SAMPLEFORMAT, is_float ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
  if (ok && compression == COMPRESSION_LZW) ok = TIFFSetField(tif.tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
  std::vector<char> row(row_bytes);
  for (int y = 0; ok && y < pixels.rows; ++y) {
    std::memcpy(row.data(), pixels.ptr<char>(y), row_bytes);  // libtiff may modify the buffer (predictor)
    ok = TIFFWriteScanline(tif.tif, row.data(), std::uint32_t(y), 0) >= 0;
  }
  if (ok) ok = TIFFWriteDirectory(tif.tif) != 0;
  TIFFClose(tif.tif);
  tif.tif = nullptr;
  if (!ok) throw runtime_failure("TIFF writer: {}", stream.message[0] ? stream.message : "libtiff failed");
  return out;
}

}  // namespace fest::formats::image_detail
