// libFuzzer target: raw bytes into the NIfTI (-1, -2, Analyze), MGH, NRRD and MetaImage readers. Whatever reads
// successfully is written back in every format (raw and compressed) and read again, so
// the writers see the odd geometry and values the readers let through.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/volume/volume_io.hpp"

namespace {

void round_trip(const fest::Volume& v) {
  using fest::formats::Format;
  if (v.size() > 4096) return;  // keep each input fast; the codecs are size-independent
  for (Format f : {Format::nifti, Format::nifti2, Format::mgh, Format::nrrd, Format::mha}) {
    for (bool compress : {false, true}) {
      try {
        const std::string bytes = fest::formats::write_volume(v, f, {compress, std::nullopt});
        (void)fest::formats::read_volume(bytes, f);
      } catch (const fest::Error&) {
        // e.g. geometry that overflows float32 in a NIfTI sform: refused cleanly
      }
    }
  }
  (void)fest::formats::describe_volume(v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  using fest::formats::Format;
  for (Format f : {Format::nifti, Format::mgh, Format::nrrd, Format::mha}) {
    try {
      round_trip(fest::formats::read_volume(bytes, f));
    } catch (const fest::Error&) {
    }
  }
  return 0;
}
