// fluidsim's two decoders (lib/fluidsim): the scene JSON (parse_scene, with its
// validation) and the frame stream (decode_frame, frame after frame until the bytes end,
// as `fluidsim render` reads it). Bytes starting with "NRRD" are a frame stream, anything
// else a scene. Any bytes must give a scene or frames, or a clean fest::Error: never a
// crash, a sanitizer report or an allocation beyond the input's own claims.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "fluidsim/frame.hpp"
#include "fluidsim/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    if (bytes.substr(0, 4) == "NRRD") {
      std::size_t pos = 0;
      long n = 0;
      while (pos < bytes.size()) {
        fest::fluidsim::Frame f;
        const std::size_t next = fest::fluidsim::decode_frame(bytes, pos, f, "fuzz", n++);
        if (next <= pos) __builtin_trap();  // no progress: a reader loop would hang
        if (f.data.size() != f.nodes() * static_cast<std::size_t>(f.channels())) __builtin_trap();
        pos = next;
      }
      return 0;
    }
    const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
    if (doc.is_discarded()) return 0;
    const fest::fluidsim::Scene scene = fest::fluidsim::parse_scene(doc, "fuzz");
    (void)scene.layout();
  } catch (const fest::Error&) {
  }
  return 0;
}
