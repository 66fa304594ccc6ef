// The textured glTF encoder of brdffit export (tools/brdffit/gltf_export.cpp), parsed back
// with nlohmann-json: buffers, bufferViews and accessors consistent with the bytes, the
// attributes decoding to the mesh and the atlas' UVs, images where the storage mode puts
// them, and the .glb container's chunk layout (glTF 2.0 specification, "Binary glTF").
#include <gtest/gtest.h>

#include <cstring>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "brdffit/synthetic_scene.hpp"
#include "brdffit/texture_atlas.hpp"
#include "gltf_export.hpp"

using namespace fest::brdffit;
using fest::brdffit_tool::encode_textured_gltf;
using fest::brdffit_tool::ImageStorage;
using fest::brdffit_tool::PngTextures;

namespace {

std::string decode_base64(const std::string& s) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : 63;
  };
  std::string out;
  // Only the low `bits` bits of acc matter; unsigned, so the shift may drop high bits
  // (a signed int overflowed after a few hundred characters: UBSan).
  int bits = 0;
  std::uint32_t acc = 0;
  for (char c : s) {
    if (c == '=') break;
    acc = (acc << 6) | static_cast<std::uint32_t>(value(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

std::uint32_t u32(const std::string& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

float f32(const std::string& b, std::size_t at) {
  float v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// Checks every accessor against its bufferView and every bufferView against the buffer.
void expect_consistent(const nlohmann::json& j, std::size_t buffer_bytes) {
  ASSERT_EQ(j["buffers"].size(), 1u);
  EXPECT_EQ(j["buffers"][0]["byteLength"].get<std::size_t>(), buffer_bytes);
  for (const auto& v : j["bufferViews"]) {
    EXPECT_LE(v["byteOffset"].get<std::size_t>() + v["byteLength"].get<std::size_t>(), buffer_bytes);
    EXPECT_EQ(v["byteOffset"].get<std::size_t>() % 4, 0u);
  }
  for (const auto& a : j["accessors"]) {
    const auto& v = j["bufferViews"][a["bufferView"].get<std::size_t>()];
    const std::string type = a["type"];
    const std::size_t comps = type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 1;
    EXPECT_EQ(a["componentType"].get<int>(), 5126);
    EXPECT_EQ(a["count"].get<std::size_t>() * comps * 4, v["byteLength"].get<std::size_t>());
  }
}

}  // namespace

TEST(BrdffitGltf, TexturedGltfDecodesToTheMeshAndTheAtlas) {
  const auto mesh = icosphere(1, 3.0);
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel_size_for(mesh, 64)));
  const PngTextures png{"PNG-base", "PNG-mr", "PNG-normal"};
  const auto g = encode_textured_gltf(mesh, atlas, png, ImageStorage::files, "obj");
  const nlohmann::json j = nlohmann::json::parse(g.bytes);
  EXPECT_EQ(j["asset"]["version"], "2.0");
  const std::string uri = j["buffers"][0]["uri"];
  const std::string prefix = "data:application/octet-stream;base64,";
  ASSERT_EQ(uri.compare(0, prefix.size(), prefix), 0);
  const std::string buf = decode_base64(uri.substr(prefix.size()));
  expect_consistent(j, buf.size());
  const auto& att = j["meshes"][0]["primitives"][0]["attributes"];
  const std::size_t n = 3 * mesh.triangles.size();
  for (const char* name : {"POSITION", "NORMAL", "TEXCOORD_0", "TANGENT"})
    EXPECT_EQ(j["accessors"][att[name].get<std::size_t>()]["count"].get<std::size_t>(), n) << name;
  // Vertex 3t + k is corner k of triangle t, its UV the atlas' uv(t, k).
  const auto& pos = j["bufferViews"][j["accessors"][att["POSITION"].get<std::size_t>()]["bufferView"].get<std::size_t>()];
  const auto& uvv = j["bufferViews"][j["accessors"][att["TEXCOORD_0"].get<std::size_t>()]["bufferView"].get<std::size_t>()];
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::size_t vtx = 3 * t + static_cast<std::size_t>(k);
      const Eigen::Vector3d& p = mesh.vertices[mesh.triangles[t][static_cast<std::size_t>(k)]];
      for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(f32(buf, pos["byteOffset"].get<std::size_t>() + vtx * 12 + static_cast<std::size_t>(c) * 4),
                        static_cast<float>(p[c]));
      const Eigen::Vector2d uv = atlas.uv(t, k);
      EXPECT_FLOAT_EQ(f32(buf, uvv["byteOffset"].get<std::size_t>() + vtx * 8), static_cast<float>(uv.x()));
      EXPECT_FLOAT_EQ(f32(buf, uvv["byteOffset"].get<std::size_t>() + vtx * 8 + 4), static_cast<float>(uv.y()));
    }
  // Images as files beside the .gltf, named after it; the material uses all three.
  ASSERT_EQ(g.images.size(), 3u);
  EXPECT_EQ(g.images[0].first, "obj_basecolor.png");
  EXPECT_EQ(g.images[2].second, "PNG-normal");
  EXPECT_EQ(j["images"][1]["uri"], "obj_metalrough.png");
  const auto& mat = j["materials"][0];
  EXPECT_EQ(j["textures"][mat["normalTexture"]["index"].get<std::size_t>()]["source"].get<std::size_t>(), 2u);
  EXPECT_EQ(mat["pbrMetallicRoughness"]["metallicFactor"].get<double>(), 1.0);
}

TEST(BrdffitGltf, GlbHoldsJsonBinaryAndImages) {
  const auto mesh = icosphere(0, 1.0);
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, 0.1));
  const PngTextures png{"base-bytes", "mr-bytes!", ""};  // no normal map
  const auto g = encode_textured_gltf(mesh, atlas, png, ImageStorage::glb, "unused");
  EXPECT_TRUE(g.images.empty());
  const std::string& b = g.bytes;
  ASSERT_GE(b.size(), 28u);
  EXPECT_EQ(b.substr(0, 4), "glTF");
  EXPECT_EQ(u32(b, 4), 2u);
  EXPECT_EQ(u32(b, 8), b.size());
  const std::uint32_t json_len = u32(b, 12);
  EXPECT_EQ(u32(b, 16), 0x4E4F534Au);
  EXPECT_EQ(json_len % 4, 0u);
  const nlohmann::json j = nlohmann::json::parse(b.substr(20, json_len));
  const std::uint32_t bin_len = u32(b, 20 + json_len);
  EXPECT_EQ(u32(b, 24 + json_len), 0x004E4942u);
  EXPECT_EQ(28 + json_len + bin_len, b.size());
  EXPECT_FALSE(j["buffers"][0].contains("uri"));
  const std::string bin = b.substr(28 + json_len, bin_len);
  expect_consistent(j, bin.size());
  EXPECT_FALSE(j["meshes"][0]["primitives"][0]["attributes"].contains("TANGENT"));
  EXPECT_FALSE(j["materials"][0].contains("normalTexture"));
  ASSERT_EQ(j["images"].size(), 2u);
  const auto& view = j["bufferViews"][j["images"][1]["bufferView"].get<std::size_t>()];
  EXPECT_EQ(bin.substr(view["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>()), "mr-bytes!");
  EXPECT_EQ(j["images"][1]["mimeType"], "image/png");
}

TEST(BrdffitGltf, DataUrisCarryTheImages) {
  const auto mesh = icosphere(0, 1.0);
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, 0.1));
  const auto g = encode_textured_gltf(mesh, atlas, {"abc", "defg", ""}, ImageStorage::data_uri, "x");
  const nlohmann::json j = nlohmann::json::parse(g.bytes);
  const std::string uri = j["images"][1]["uri"];
  const std::string prefix = "data:image/png;base64,";
  ASSERT_EQ(uri.compare(0, prefix.size(), prefix), 0);
  EXPECT_EQ(decode_base64(uri.substr(prefix.size())), "defg");
}
