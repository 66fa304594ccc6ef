// libFuzzer target for the image readers: the bytes go to every image format's header
// parser, and where a header is accepted and small, to the full reader and back out
// through the writer. Only fest::Error may escape the library; anything else (a crash,
// a sanitizer report, another exception type) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"

namespace {

using fest::formats::Format;

// Keeps each run fast: decoding is only attempted for modest images.
constexpr std::uint64_t max_fuzz_values = std::uint64_t{1} << 22;

void exercise(std::string_view bytes, Format format) {
  fest::formats::ImageHeader header;
  try {
    header = fest::formats::read_image_header(bytes, format);
  } catch (const fest::Error&) {
    return;
  }
  if (std::uint64_t(header.width) * std::uint64_t(header.height) * std::uint64_t(header.channels) > max_fuzz_values)
    return;
  try {
    const fest::Image image = fest::formats::read_image(bytes, format);
    (void)fest::formats::write_image(image, format);
  } catch (const fest::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (Format f : {Format::png, Format::pgm, Format::ppm, Format::pam, Format::pfm, Format::exr, Format::tiff,
                   Format::jpeg})
    exercise(bytes, f);
  return 0;
}
