#include "formats/image/codec_plugins.hpp"

#include "core/error.hpp"
#include "formats/plugin_loader.hpp"

namespace fest::formats::image_detail {
namespace {

template <class Table>
const Table& checked(const Table* table, const char* file) {
  if (!table || table->abi != kCodecPluginAbi || table->size != sizeof(Table))
    throw io_error("{} is from another fest build; reinstall fest", file);
  return *table;
}

}  // namespace

const TiffCodec& tiff_codec() {
  static constexpr PluginModule kModule{"libfest_tiff_plugin.so", "fest_tiff_codec_table", "TIFF support", "libtiff6"};
  return checked(plugin_table<TiffCodec>(kModule), kModule.file);
}

const ExrCodec& exr_codec() {
  static constexpr PluginModule kModule{"libfest_exr_plugin.so", "fest_exr_codec_table", "OpenEXR support",
                                        "libopenexr-3-1-30"};
  return checked(plugin_table<ExrCodec>(kModule), kModule.file);
}

}  // namespace fest::formats::image_detail

// The public EXR-with-extras calls (exr_extras.hpp) go through the module too.
namespace fest::formats {

std::string write_exr_with_extras(const cv::Mat& rgb, const ExrExtras& extras, bool half) {
  return image_detail::exr_codec().write_with_extras(rgb, extras, half);
}

cv::Mat read_exr_channel(std::string_view bytes, const std::string& name) {
  return image_detail::exr_codec().read_channel(bytes, name);
}

ExrExtras read_exr_attributes(std::string_view bytes) { return image_detail::exr_codec().read_attributes(bytes); }

}  // namespace fest::formats
