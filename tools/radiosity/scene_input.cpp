#include "scene_input.hpp"

#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/mesh/attributed_ply.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "radiosity/scene_json.hpp"

namespace fest::radiosity_tool {

namespace {

const formats::PlyColumn* column(const std::vector<formats::PlyColumn>& cols, const char* name) {
  for (const auto& c : cols)
    if (c.name == name) return &c;
  return nullptr;
}

// A PLY whose faces carry object_id (optional), refl_r refl_g refl_b and emit_r emit_g
// emit_b (optional): one object per object id and material, named from the header's
// "object <id> <name>" comments when present (what solve writes), else "object<id>".
radiosity::Scene scene_from_ply(std::string_view bytes) {
  const formats::AttributedPly ply = formats::read_attributed_ply(bytes);
  const formats::PlyColumn *x = column(ply.vertex, "x"), *y = column(ply.vertex, "y"), *z = column(ply.vertex, "z");
  if (!x || !y || !z) throw bad_input("PLY scene: the vertices have no x, y, z");
  const formats::PlyColumn* refl[3] = {column(ply.face, "refl_r"), column(ply.face, "refl_g"), column(ply.face, "refl_b")};
  const formats::PlyColumn* emit[3] = {column(ply.face, "emit_r"), column(ply.face, "emit_g"), column(ply.face, "emit_b")};
  const formats::PlyColumn* oid = column(ply.face, "object_id");
  if (!refl[0] || !refl[1] || !refl[2])
    throw bad_input("PLY scene: faces need the properties refl_r, refl_g, refl_b (and emit_r, emit_g, emit_b)");
  if ((emit[0] != nullptr) != (emit[1] != nullptr) || (emit[0] != nullptr) != (emit[2] != nullptr))
    throw bad_input("PLY scene: give all of emit_r, emit_g, emit_b or none");
  std::map<long long, std::string> names;
  for (const std::string& c : ply.comments) {
    std::istringstream in(c);
    std::string word, name;
    long long id;
    if (in >> word >> id >> name && word == "object") names[id] = name;
  }
  radiosity::Scene scene;
  std::map<std::tuple<long long, double, double, double, double, double, double>, std::size_t> object_of;
  std::vector<std::map<std::uint32_t, std::uint32_t>> remap;
  for (std::size_t f = 0; f < ply.faces.size(); ++f) {
    const long long id = oid ? static_cast<long long>(oid->values[f]) : 0;
    const radiosity::Rgb r(refl[0]->values[f], refl[1]->values[f], refl[2]->values[f]);
    const radiosity::Rgb e = emit[0] ? radiosity::Rgb(emit[0]->values[f], emit[1]->values[f], emit[2]->values[f])
                                     : radiosity::Rgb::Zero();
    const auto key = std::make_tuple(id, r[0], r[1], r[2], e[0], e[1], e[2]);
    auto it = object_of.find(key);
    if (it == object_of.end()) {
      radiosity::SceneObject o;
      o.name = names.count(id) ? names[id] : "object" + std::to_string(id);
      std::size_t same = 0;
      for (const auto& [k, v] : object_of)
        if (std::get<0>(k) == id) ++same;
      if (same > 0) o.name += "#" + std::to_string(same);
      o.reflectance = r;
      o.emission = e;
      it = object_of.emplace(key, scene.objects.size()).first;
      scene.objects.push_back(o);
      remap.emplace_back();
    }
    radiosity::SceneObject& o = scene.objects[it->second];
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : ply.faces[f]) {
      auto [m, fresh] = remap[it->second].emplace(v, static_cast<std::uint32_t>(o.vertices.size()));
      if (fresh) o.vertices.emplace_back(x->values[v], y->values[v], z->values[v]);
      face.push_back(m->second);
    }
    o.faces.push_back(std::move(face));
  }
  return scene;
}

}  // namespace

radiosity::Scene read_scene(const std::string& path) {
  const std::string bytes = read_input(path);
  const std::string where = input_name(path);
  std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw bad_input("empty scene ({})", where);
  if (bytes.compare(0, 4, "ply\n") == 0 || bytes.compare(0, 5, "ply\r\n") == 0) {
    try {
      return scene_from_ply(bytes);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), where));
    }
  }
  if (bytes[first] != '{') throw bad_input("scene is neither JSON nor PLY ({})", where);
  radiosity::SceneFile file;
  try {
    file = radiosity::decode_scene_json(bytes);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), input_name(path)));
  }
  const std::filesystem::path base =
      is_stdio(path) ? std::filesystem::current_path() : std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < file.scene.objects.size(); ++i) {
    if (file.mesh_paths[i].empty()) continue;
    std::filesystem::path mp(file.mesh_paths[i]);
    if (mp.is_relative()) mp = base / mp;
    // load_input + read_mesh(Input): a glTF's external buffers are found beside the mesh.
    const Mesh mesh = formats::parse(formats::load_input(mp.string()), formats::read_mesh);
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
