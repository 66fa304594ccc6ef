#pragma once
// Raw Netpbm (P5, P6, P7) and PFM files read a band of rows at a time, straight from the
// file: a large image can flow through a computation (resample resize) without ever being
// in memory whole, as the formats' fixed row layout allows. Samples come out as
// read_image gives them: rows top to bottom, native byte order.

#include <cstdint>
#include <memory>
#include <string>

#include "core/image.hpp"
#include "formats/image/image_io.hpp"

namespace fest::formats {

class NetpbmRowFile {
 public:
  // The file at `path` when it is a regular file holding a raw Netpbm image with maxval
  // 255 or 65535 (no sample can then exceed it) or a PFM image; nullptr for anything
  // else (other formats, ASCII Netpbm, other maxvals, gzip, standard input), which the
  // caller reads whole with read_image. A header read_image would refuse, or data
  // shorter than the header promises, throws the same bad_input (naming `path`).
  static std::unique_ptr<NetpbmRowFile> open(const std::string& path);
  ~NetpbmRowFile();
  NetpbmRowFile(const NetpbmRowFile&) = delete;
  NetpbmRowFile& operator=(const NetpbmRowFile&) = delete;

  const ImageHeader& header() const { return header_; }
  int cv_type() const;              // CV_8UC(c), CV_16UC(c) or CV_32FC(c)
  ColorSpace color_space() const;   // as read_image gives it: linear for PFM
  std::size_t row_bytes() const;    // of one row in memory

  // Image rows [first, last) into dst, rows packed (row_bytes() each). Safe to call
  // from several threads at once (positioned reads). Throws Status::io when the file
  // cannot be read or has shrunk.
  void read_rows(int first, int last, void* dst) const;

 private:
  NetpbmRowFile() = default;
  std::string path_;
  int fd_ = -1;
  ImageHeader header_;
  std::uint64_t data_offset_ = 0;
  bool pfm_ = false, swap_ = false;
};

}  // namespace fest::formats
