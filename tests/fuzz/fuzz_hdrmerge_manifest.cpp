// hdrmerge session's reading of a capture manifest (tools/hdrmerge/session_manifest:
// parse_session_manifest): the sets and silhouettes it will merge, decided before any
// picture is opened. Any bytes must give a manifest or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "session_manifest.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
  if (doc.is_discarded()) return 0;
  try {
    const fest::hdrmerge_tool::SessionManifest m = fest::hdrmerge_tool::parse_session_manifest(doc, "manifest");
    for (const auto& set : m.sets)
      if (set.exposures.size() < 2 || set.light.empty()) __builtin_trap();  // the checks it promises
  } catch (const fest::Error&) {
  }
  return 0;
}
