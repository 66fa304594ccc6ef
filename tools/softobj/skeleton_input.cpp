#include "skeleton_input.hpp"

#include "core/error.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "softobj/skeleton_json.hpp"

namespace fest::softobj_tool {

softobj::Skeleton read_skeleton(const std::string& path, SkeletonFormat format) {
  const formats::Input in = formats::load_input(path);
  if (format == SkeletonFormat::json) {
    if (in.format != formats::Format::json)
      throw bad_input("the skeleton is {}, not JSON ({}); a mesh skeleton needs --skeleton-format mesh",
                      formats::format_name(in.format), in.name);
    return formats::parse(in, [](std::string_view b, formats::Format) { return softobj::decode_skeleton(b); });
  }
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("the skeleton is {}, not a mesh ({})", formats::format_name(in.format), in.name);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  if (const auto skipped = formats::skipped_faces(mesh))
    throw bad_input("{} faces of the skeleton mesh are not manifold and would be lost ({})", skipped, in.name);
  softobj::Skeleton s;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    s.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (auto f : mesh.faces()) {
    std::vector<int> idx;
    for (auto v : mesh.fv_range(f)) idx.push_back(v.idx());
    for (std::size_t k = 1; k + 1 < idx.size(); ++k) s.triangles.push_back({idx[0], idx[k], idx[k + 1]});  // fan
  }
  if (s.triangles.empty()) throw bad_input("the skeleton mesh has no faces ({})", in.name);
  softobj::validate(s);
  return s;
}

}  // namespace fest::softobj_tool
