#include "scene_input.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "radiosity/scene_json.hpp"

namespace fest::radiosity_tool {

radiosity::Scene read_scene(const std::string& path) {
  const std::string bytes = read_input(path);
  std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw bad_input("empty scene ({})", is_stdio(path) ? "standard input" : path);
  if (bytes[first] != '{')
    throw bad_input("scene is not a JSON object ({}); PLY scenes are not supported, describe the scene in JSON",
                    is_stdio(path) ? "standard input" : path);
  radiosity::SceneFile file;
  try {
    file = radiosity::decode_scene_json(bytes);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), is_stdio(path) ? "standard input" : path));
  }
  const std::filesystem::path base =
      is_stdio(path) ? std::filesystem::current_path() : std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < file.scene.objects.size(); ++i) {
    if (file.mesh_paths[i].empty()) continue;
    std::filesystem::path mp(file.mesh_paths[i]);
    if (mp.is_relative()) mp = base / mp;
    const std::string mesh_bytes = read_input(mp.string());
    Mesh mesh;
    try {
      mesh = formats::read_mesh(mesh_bytes, formats::detect_format(mesh_bytes, mp.string()));
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), mp.string()));
    }
    if (const std::size_t skipped = formats::skipped_faces(mesh); skipped > 0)
      throw bad_input("{} face(s) the mesh structure cannot hold (non-manifold) ({})", skipped, mp.string());
    radiosity::SceneObject& o = file.scene.objects[i];
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      o.vertices.emplace_back(p[0], p[1], p[2]);
    }
    for (auto fh : mesh.faces()) {
      std::vector<std::uint32_t> face;
      for (auto vh : mesh.fv_range(fh)) face.push_back(static_cast<std::uint32_t>(vh.idx()));
      o.faces.push_back(std::move(face));
    }
    if (file.transforms[i]) radiosity::apply_transform(o, *file.transforms[i]);
  }
  return file.scene;
}

}  // namespace fest::radiosity_tool
