#include "gltf_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdffit/pbr_appearance.hpp"
#include "brdffit/texture_bake.hpp"

namespace fest::brdffit_tool {
namespace {

std::string base64(const std::vector<std::uint8_t>& in) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::uint32_t b0 = in[i], b1 = i + 1 < in.size() ? in[i + 1] : 0, b2 = i + 2 < in.size() ? in[i + 2] : 0;
    const std::uint32_t v = b0 << 16 | b1 << 8 | b2;
    out.push_back(table[v >> 18 & 63]);
    out.push_back(table[v >> 12 & 63]);
    out.push_back(i + 1 < in.size() ? table[v >> 6 & 63] : '=');
    out.push_back(i + 2 < in.size() ? table[v & 63] : '=');
  }
  return out;
}

void put_f32(std::vector<std::uint8_t>& b, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  for (int k = 0; k < 4; ++k) b.push_back(static_cast<std::uint8_t>(bits >> (8 * k)));
}
void put_u32(std::vector<std::uint8_t>& b, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) b.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

}  // namespace

std::string encode_gltf(const reflectance::TriangleMesh& mesh, const reflectance::SurfaceMaterials& mats) {
  const std::size_t m = mats.brdfs.size();
  std::vector<std::vector<std::uint32_t>> indices(m);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::size_t id = 0;
    if (mats.vertex_weights.empty()) {
      id = mats.triangle_material[t];
    } else {
      const float* w = &mats.vertex_weights[mesh.triangles[t][0] * m];
      id = static_cast<std::size_t>(std::max_element(w, w + m) - w);
    }
    for (std::uint32_t v : mesh.triangles[t]) indices[id].push_back(v);
  }
  std::vector<std::uint8_t> buf;
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  for (const auto& v : mesh.vertices) {
    const Eigen::Vector3f f = v.cast<float>();
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
    for (int k = 0; k < 3; ++k) put_f32(buf, f[k]);
  }
  const std::size_t pos_bytes = buf.size();
  for (const auto& n : mesh.normals)
    for (int k = 0; k < 3; ++k) put_f32(buf, static_cast<float>(n[k]));
  const std::size_t nrm_bytes = buf.size() - pos_bytes;
  nlohmann::json j;
  j["asset"] = {{"version", "2.0"}, {"generator", "fest brdffit export"}};
  j["scene"] = 0;
  j["scenes"] = {{{"nodes", {0}}}};
  j["nodes"] = {{{"mesh", 0}}};
  j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", pos_bytes}, {"target", 34962}},
                      {{"buffer", 0}, {"byteOffset", pos_bytes}, {"byteLength", nrm_bytes}, {"target", 34962}}};
  const auto nv = mesh.vertices.size();
  j["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"},
                     {"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}},
                    {{"bufferView", 1}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"}}};
  j["meshes"] = {{{"primitives", nlohmann::json::array()}}};
  j["materials"] = nlohmann::json::array();
  for (std::size_t k = 0; k < m; ++k) {
    const auto& b = mats.brdfs[k];
    const Eigen::Vector3d base = b.rho_d.cwiseMax(0.0).cwiseMin(1.0);
    j["materials"].push_back({{"name", "lafortune_" + std::to_string(k)},
                              {"pbrMetallicRoughness",
                               {{"baseColorFactor", {base.x(), base.y(), base.z(), 1.0}},
                                {"metallicFactor", 0.0},
                                {"roughnessFactor", brdffit::pbr_roughness(b)}}}});
    if (indices[k].empty()) continue;
    const std::size_t offset = buf.size();
    for (std::uint32_t i : indices[k]) put_u32(buf, i);
    j["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", buf.size() - offset}, {"target", 34963}});
    j["accessors"].push_back({{"bufferView", j["bufferViews"].size() - 1},
                              {"componentType", 5125},
                              {"count", indices[k].size()},
                              {"type", "SCALAR"}});
    j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                                           {"indices", j["accessors"].size() - 1},
                                           {"material", k}});
  }
  j["buffers"] = {{{"byteLength", buf.size()}, {"uri", "data:application/octet-stream;base64," + base64(buf)}}};
  return j.dump() + "\n";
}

namespace {

void pad_to_4(std::vector<std::uint8_t>& b, std::uint8_t with) {
  while (b.size() % 4) b.push_back(with);
}

}  // namespace

GltfFile encode_textured_gltf(const reflectance::TriangleMesh& mesh, const brdffit::TextureAtlas& atlas,
                              const PngTextures& textures, ImageStorage storage, const std::string& image_stem) {
  const std::size_t nt = mesh.triangles.size();
  const bool with_normal_map = !textures.normal.empty();
  std::vector<std::uint8_t> buf;
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();
  auto add_view = [&](std::size_t offset, std::size_t length, bool vertex_data) {
    nlohmann::json v{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    if (vertex_data) v["target"] = 34962;  // ARRAY_BUFFER
    views.push_back(v);
    return views.size() - 1;
  };
  // Vertex attributes, three vertices per triangle, one bufferView each.
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  std::size_t offset = buf.size();
  for (const auto& tri : mesh.triangles)
    for (std::uint32_t v : tri) {
      const Eigen::Vector3f f = mesh.vertices[v].cast<float>();
      lo = lo.cwiseMin(f);
      hi = hi.cwiseMax(f);
      for (int k = 0; k < 3; ++k) put_f32(buf, f[k]);
    }
  accessors.push_back({{"bufferView", add_view(offset, buf.size() - offset, true)}, {"componentType", 5126},
                       {"count", 3 * nt}, {"type", "VEC3"}, {"min", {lo.x(), lo.y(), lo.z()}},
                       {"max", {hi.x(), hi.y(), hi.z()}}});
  offset = buf.size();
  for (const auto& tri : mesh.triangles)
    for (std::uint32_t v : tri)
      for (int k = 0; k < 3; ++k) put_f32(buf, static_cast<float>(mesh.normals[v][k]));
  accessors.push_back({{"bufferView", add_view(offset, buf.size() - offset, true)}, {"componentType", 5126},
                       {"count", 3 * nt}, {"type", "VEC3"}});
  offset = buf.size();
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d uv = atlas.uv(t, k);
      put_f32(buf, static_cast<float>(uv.x()));
      put_f32(buf, static_cast<float>(uv.y()));
    }
  accessors.push_back({{"bufferView", add_view(offset, buf.size() - offset, true)}, {"componentType", 5126},
                       {"count", 3 * nt}, {"type", "VEC2"}});
  nlohmann::json attributes{{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}};
  if (with_normal_map) {
    offset = buf.size();
    for (const auto& corners : brdffit::corner_tangents(mesh, atlas))
      for (const Eigen::Vector4d& tan : corners)
        for (int k = 0; k < 4; ++k) put_f32(buf, static_cast<float>(tan[k]));
    accessors.push_back({{"bufferView", add_view(offset, buf.size() - offset, true)}, {"componentType", 5126},
                         {"count", 3 * nt}, {"type", "VEC4"}});
    attributes["TANGENT"] = 3;
  }

  // Images: in the binary buffer (glb), as data URIs, or as files beside the .gltf.
  GltfFile out;
  nlohmann::json images = nlohmann::json::array();
  auto add_image = [&](const std::string& png, const std::string& suffix) {
    if (storage == ImageStorage::glb) {
      pad_to_4(buf, 0);
      const std::size_t at = buf.size();
      buf.insert(buf.end(), png.begin(), png.end());
      images.push_back({{"bufferView", add_view(at, png.size(), false)}, {"mimeType", "image/png"}});
    } else if (storage == ImageStorage::data_uri) {
      images.push_back({{"uri", "data:image/png;base64," + base64(std::vector<std::uint8_t>(png.begin(), png.end()))}});
    } else {
      const std::string name = image_stem + "_" + suffix + ".png";
      images.push_back({{"uri", name}});
      out.images.emplace_back(name, png);
    }
    return images.size() - 1;
  };
  const std::size_t base_image = add_image(textures.base_color, "basecolor");
  const std::size_t mr_image = add_image(textures.metallic_roughness, "metalrough");
  nlohmann::json material{{"name", "lafortune_pbr"},
                          {"pbrMetallicRoughness",
                           {{"baseColorTexture", {{"index", 0}}},
                            {"metallicRoughnessTexture", {{"index", 1}}},
                            {"metallicFactor", 1.0},
                            {"roughnessFactor", 1.0}}}};
  nlohmann::json tex = {{{"sampler", 0}, {"source", base_image}}, {{"sampler", 0}, {"source", mr_image}}};
  if (with_normal_map) {
    tex.push_back({{"sampler", 0}, {"source", add_image(textures.normal, "normal")}});
    material["normalTexture"] = {{"index", 2}};
  }

  nlohmann::json j;
  j["asset"] = {{"version", "2.0"}, {"generator", "fest brdffit export"}};
  j["scene"] = 0;
  j["scenes"] = {{{"nodes", {0}}}};
  j["nodes"] = {{{"mesh", 0}}};
  j["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"material", 0}, {"mode", 4}}}}}};
  j["materials"] = {material};
  // 9729 LINEAR for both filters (no mipmaps), 33071 CLAMP_TO_EDGE.
  j["samplers"] = {{{"magFilter", 9729}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33071}}};
  j["textures"] = tex;
  j["images"] = images;
  j["accessors"] = accessors;
  j["bufferViews"] = views;
  if (storage == ImageStorage::glb) {
    pad_to_4(buf, 0);
    j["buffers"] = {{{"byteLength", buf.size()}}};
    std::string text = j.dump();
    while (text.size() % 4) text.push_back(' ');
    std::vector<std::uint8_t> glb;
    put_u32(glb, 0x46546C67u);  // "glTF"
    put_u32(glb, 2);
    put_u32(glb, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + buf.size()));
    put_u32(glb, static_cast<std::uint32_t>(text.size()));
    put_u32(glb, 0x4E4F534Au);  // "JSON"
    glb.insert(glb.end(), text.begin(), text.end());
    put_u32(glb, static_cast<std::uint32_t>(buf.size()));
    put_u32(glb, 0x004E4942u);  // "BIN\0"
    glb.insert(glb.end(), buf.begin(), buf.end());
    out.bytes.assign(glb.begin(), glb.end());
  } else {
    j["buffers"] = {{{"byteLength", buf.size()}, {"uri", "data:application/octet-stream;base64," + base64(buf)}}};
    out.bytes = j.dump() + "\n";
  }
  return out;
}

}  // namespace fest::brdffit_tool
