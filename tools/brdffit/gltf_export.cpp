#include "gltf_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

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

double gltf_roughness(const reflectance::LafortuneBrdf& brdf) {
  double best_peak = -1, n = 0;
  for (const auto& lobe : brdf.lobes) {
    // Peak of max(0, Cxy (ux vx + uy vy) + Cz uz vz)^N over mirror-like pairs: the base's
    // largest value is max(|Cxy|, |Cz|) when the lobe is mirror-like (Cxy < 0 < Cz).
    const double base = std::max(std::abs(lobe.cxy.mean()), std::abs(lobe.cz.mean()));
    const double peak = std::pow(base, lobe.n.mean());
    if (peak > best_peak) {
      best_peak = peak;
      n = lobe.n.mean();
    }
  }
  return brdf.lobes.empty() ? 1.0 : std::sqrt(2.0 / (n + 2.0));
}

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
                                {"roughnessFactor", gltf_roughness(b)}}}});
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

}  // namespace fest::brdffit_tool
