#pragma once
// Header parsers of each image format, written by hand so that nothing with an absurd
// or inconsistent header ever reaches a decoder (OpenCV, libpng, libtiff, OpenEXR).
// Every parser validates sizes with check_dimensions() and throws bad_input.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/image/image_io.hpp"

namespace fest::formats::image_detail {

ImageHeader read_png_header(std::string_view bytes);
ImageHeader read_tiff_header(std::string_view bytes);
ImageHeader read_exr_header(std::string_view bytes);
ImageHeader read_jpeg_header(std::string_view bytes);

// The Netpbm family (P2, P3, P5, P6, P7) and PFM: everything a decoder needs to know.
struct NetpbmLayout {
  ImageHeader header;
  char magic = 0;              // '2', '3', '5', '6', '7', 'F' (PF colour), 'f' (Pf grey)
  bool ascii = false;          // P2/P3: samples as decimal text
  unsigned maxval = 0;         // integer formats
  bool big_endian = false;     // PFM: scale > 0
  std::size_t data_offset = 0; // first byte after the header
};

// `format` only names the format in messages; any Netpbm magic is accepted for
// pgm/ppm/pam (they are one family), PF/Pf for pfm. Checks the data is long enough
// for what the header promises (exactly, for raw data) before anything is allocated.
NetpbmLayout read_netpbm_layout(std::string_view bytes, bool pfm);
// The same from the first bytes of a file of `total_size` bytes (netpbm_rows.cpp reads
// the header only): the header must lie within `bytes`, the data size is checked
// against total_size.
NetpbmLayout read_netpbm_layout(std::string_view bytes, bool pfm, std::uint64_t total_size);

}  // namespace fest::formats::image_detail

namespace fest::formats::image_detail {
const char* format_name_of(Format f);  // "PNG", "TIFF", ... for messages
}  // namespace fest::formats::image_detail
