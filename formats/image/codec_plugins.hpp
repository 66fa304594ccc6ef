#pragma once
// TIFF and OpenEXR live in plugin modules (libfest_tiff_plugin.so, libfest_exr_plugin.so)
// that image_io opens only when a TIFF or EXR is read or written: libtiff maps seven
// shared libraries and OpenEXR four, which every image tool would otherwise load at
// start-up (formats/plugin_loader.hpp). Each module exports one function returning the
// table below. Both sides are built from this tree with the same compiler, so the table
// carries C++ types; `abi` and `size` catch a module left over from another build.

#include <cstddef>
#include <string>
#include <string_view>

#include "core/image.hpp"
#include "core/progress_fn.hpp"
#include "formats/image/exr_extras.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats::image_detail {

// Bump when a table below changes.
inline constexpr int kCodecPluginAbi = 2;

struct TiffCodec {
  int abi;
  std::size_t size;  // sizeof(TiffCodec) in the module's build
  cv::Mat (*decode)(std::string_view bytes, const ImageHeader& expected);
  std::string (*encode)(const cv::Mat& pixels);
};

struct ExrCodec {
  int abi;
  std::size_t size;
  cv::Mat (*decode)(std::string_view bytes);
  std::string (*encode)(const cv::Mat& pixels, bool half, const ProgressFn& progress);
  std::string (*write_with_extras)(const cv::Mat& rgb, const ExrExtras& extras, bool half);
  cv::Mat (*read_channel)(std::string_view bytes, const std::string& name);
  ExrExtras (*read_attributes)(std::string_view bytes);
};

// Load the module on first use; throw Status::io (exit 4) naming the Debian package when
// it or its library cannot be loaded.
const TiffCodec& tiff_codec();
const ExrCodec& exr_codec();

}  // namespace fest::formats::image_detail

extern "C" {
// The modules' entry points (tiff_plugin.cpp, exr_plugin.cpp).
const fest::formats::image_detail::TiffCodec* fest_tiff_codec_table();
const fest::formats::image_detail::ExrCodec* fest_exr_codec_table();
}
