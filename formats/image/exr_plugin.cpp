// libfest_exr_plugin.so's entry point (codec_plugins.hpp): the codec of exr_codec.cpp.
#include "formats/image/codec_plugins.hpp"
#include "formats/image/image_codecs.hpp"

extern "C" __attribute__((visibility("default"))) const fest::formats::image_detail::ExrCodec* fest_exr_codec_table() {
  using namespace fest::formats::image_detail;
  static const ExrCodec table{kCodecPluginAbi, sizeof(ExrCodec), &decode_exr, &encode_exr,
                              &exr_write_with_extras, &exr_read_channel, &exr_read_attributes};
  return &table;
}
