// The content sniffing that decides, before the assimp plugin is opened, that bytes are a
// scene (formats/detect.cpp: detect_format, scene_signature, is_gltf_json): GLB, FBX
// (binary and ascii), DirectX .x, LightWave, 3DS by their signatures, text glTF and
// COLLADA among JSON and XML. Any bytes must give a format or a clean fest::Error, and the
// answer must agree with the signatures as docs/fconv.md states them: bytes that carry
// one of the unambiguous signatures are that scene format, and a scene format is never
// answered for bytes that do not carry its mark (an abort is a finding).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"
#include "formats/detect.hpp"

namespace {

using fest::formats::Format;

std::uint32_t le32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

bool starts(std::string_view b, std::string_view prefix) { return b.substr(0, prefix.size()) == prefix; }

// The signatures of docs/fconv.md ("Scene formats"), written out again independently.
bool glb_mark(std::string_view b) { return b.size() >= 12 && starts(b, "glTF") && le32(b, 4) == 2; }
bool fbx_mark(std::string_view b) {
  return starts(b, std::string_view("Kaydara FBX Binary  \0", 21)) || starts(b, "; FBX ");
}
bool x_mark(std::string_view b) { return starts(b, "xof 03"); }
bool lwo_mark(std::string_view b) {
  if (b.size() < 12 || !starts(b, "FORM")) return false;
  const std::string_view kind = b.substr(8, 4);
  return kind == "LWO2" || kind == "LWOB" || kind == "LWLO";
}
bool threeds_mark(std::string_view b) {
  if (b.size() < 16 || b[0] != 0x4D || b[1] != 0x4D || le32(b, 2) != b.size()) return false;
  const unsigned next = static_cast<unsigned char>(b[6]) | static_cast<unsigned char>(b[7]) << 8;
  return next == 0x0002 || next == 0x3D3D;
}

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view b(reinterpret_cast<const char*>(data), size);
  Format format;
  try {
    format = fest::formats::detect_format(b, "fuzz");
  } catch (const fest::Error&) {
    // Refused: then no scene signature may have been present.
    require(!glb_mark(b) && !fbx_mark(b) && !x_mark(b) && !lwo_mark(b) && !threeds_mark(b));
    return 0;
  }
  require(fest::formats::detect_format(b, "fuzz") == format);  // deterministic
  // A signature decides, whatever else the bytes hold (no other format has these marks).
  if (glb_mark(b)) require(format == Format::glb);
  if (fbx_mark(b)) require(format == Format::fbx);
  if (x_mark(b)) require(format == Format::xfile);
  if (lwo_mark(b)) require(format == Format::lwo);
  if (threeds_mark(b)) require(format == Format::threeds);
  // And a scene format is answered only with its mark.
  switch (format) {
    case Format::glb: require(glb_mark(b)); break;
    case Format::fbx: require(fbx_mark(b)); break;
    case Format::xfile: require(x_mark(b)); break;
    case Format::lwo: require(lwo_mark(b)); break;
    case Format::threeds: require(threeds_mark(b)); break;
    case Format::dae: require(b.find("<COLLADA") != std::string_view::npos); break;
    case Format::gltf:
      require(b.find("\"asset\"") != std::string_view::npos && b.find("\"meshes\"") != std::string_view::npos);
      break;
    default: require(!fest::formats::read_only_scene_format(format)); break;
  }
  if (fest::formats::read_only_scene_format(format))
    require(fest::formats::kind_of(format) == fest::formats::Kind::mesh);
  return 0;
}
