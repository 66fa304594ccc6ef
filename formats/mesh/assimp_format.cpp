// Scene formats fest does not parse itself (glTF/GLB, COLLADA, FBX, 3DS, DirectX .x,
// LightWave), read through the assimp plugin (assimp_plugin_api.h), which is opened only
// when such a file arrives. The flattened scene becomes a fest mesh; what a fest mesh
// cannot hold is counted in unread_parts() (fconv refuses it unless
// --drop-unrepresentable), and what is not geometry at all (materials, textures,
// cameras, lights) is named in a read warning. docs/fconv.md, "Scene formats through
// assimp".

#include <string>
#include <utility>

#include "core/error.hpp"
#include "formats/mesh/assimp_plugin_api.h"
#include "formats/mesh/assimp_scene.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"
#include "formats/plugin_loader.hpp"

namespace fest::formats::mesh_detail {
namespace {

const FestAssimpPluginTable& assimp_plugin() {
  // Debian 12's libassimp5 holds libassimp.so.5: a plugin that does not load almost
  // always means it is missing.
  static constexpr PluginModule kModule{"libfest_assimp_plugin.so", "fest_assimp_plugin_table",
                                        "glTF/COLLADA/FBX/3DS support", "libassimp5"};
  const FestAssimpPluginTable* table = plugin_table<FestAssimpPluginTable>(kModule);
  if (table->abi != FEST_ASSIMP_PLUGIN_ABI || table->layout != sizeof(AssimpScene))
    throw io_error("glTF/COLLADA/FBX/3DS support is not available (libfest_assimp_plugin.so is from another fest "
                   "version); reinstall fest");
  return *table;
}

std::string list(const std::vector<std::pair<std::string, std::size_t>>& parts) {
  std::string out;
  for (const auto& [what, n] : parts) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  return out;
}

}  // namespace

Mesh read_assimp(std::string_view bytes, Format format, const std::optional<std::string>& folder) {
  const FestAssimpPluginTable& plugin = assimp_plugin();
  AssimpScene scene;
  char message[512] = "";
  const std::string hint = format == Format::threeds ? "3ds" : format == Format::xfile ? "x" : format_name(format);
  if (int status = plugin.read_scene(bytes.data(), bytes.size(), hint.c_str(), folder ? folder->c_str() : nullptr,
                                     &scene, message, sizeof message))
    throw Error(static_cast<Status>(status), fmt::format("{} (through assimp): {}", format_name(format), message));
  const std::size_t n = scene.positions.size() / 3;
  if (n > max_element_count || scene.triangles.size() / 3 > max_element_count)
    throw bad_input("{}: {} vertices are more than fest can hold", format_name(format), n);

  Mesh mesh;
  const bool normals = scene.normals.size() == 3 * n && n > 0;
  const bool colors = scene.colors.size() == 4 * n && n > 0;
  const bool texcoords = scene.texcoords.size() == 2 * n && n > 0;
  if (normals) mesh.request_vertex_normals();
  if (colors) mesh.request_vertex_colors();
  if (texcoords) mesh.request_vertex_texcoords2D();
  mesh.reserve(n, n + scene.triangles.size() / 3, scene.triangles.size() / 3);
  std::size_t translucent = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &scene.positions[3 * i];
    const Mesh::VertexHandle vh = mesh.add_vertex(Mesh::Point(p[0], p[1], p[2]));
    if (normals) mesh.set_normal(vh, Mesh::Normal(scene.normals[3 * i], scene.normals[3 * i + 1], scene.normals[3 * i + 2]));
    if (colors) {
      const float* c = &scene.colors[4 * i];
      mesh.set_color(vh, Mesh::Color(color_from_unit(c[0]), color_from_unit(c[1]), color_from_unit(c[2])));
      translucent += c[3] < 1.0f;
    }
    if (texcoords) mesh.set_texcoord2D(vh, Mesh::TexCoord2D(scene.texcoords[2 * i], scene.texcoords[2 * i + 1]));
  }
  // assimp's coordinates are float32: a binary writer may keep them as floats.
  set_point_storage(mesh, CoordinateStorage::binary);
  set_normal_storage(mesh, CoordinateStorage::binary);
  MeshBuilder builder(mesh, format_name(format));
  for (std::size_t t = 0; t + 2 < scene.triangles.size(); t += 3) builder.add_face(&scene.triangles[t], 3, t / 3 + 1);
  builder.finish();

  std::vector<MeshPart> lost;
  for (const auto& [what, count] : scene.lost) lost.push_back(MeshPart{what, count});
  if (translucent > 0) lost.push_back(MeshPart{"vertex colour alpha values below 1", translucent});
  if (!lost.empty()) set_unread_parts(mesh, std::move(lost));
  if (!scene.not_geometry.empty())
    add_read_warning(mesh, fmt::format("not read: {} (a fest mesh is geometry only)", list(scene.not_geometry)));
  return mesh;
}

}  // namespace fest::formats::mesh_detail
