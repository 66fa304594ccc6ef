// libfest_tiff_plugin.so's entry point (codec_plugins.hpp): the codec of tiff_codec.cpp.
#include "formats/image/codec_plugins.hpp"
#include "formats/image/image_codecs.hpp"

extern "C" __attribute__((visibility("default"))) const fest::formats::image_detail::TiffCodec* fest_tiff_codec_table() {
  using namespace fest::formats::image_detail;
  static const TiffCodec table{kCodecPluginAbi, sizeof(TiffCodec), &decode_tiff, &encode_tiff};
  return &table;
}
