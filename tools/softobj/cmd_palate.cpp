// softobj palate: pass 2 of the penetration avoidance on a mesh (docs/softobj.md §4.1).
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "mesh_output.hpp"
#include "softobj/palate.hpp"

namespace fest::softobj_tool {

int run_palate(const PalateArgs& a) {
  if (a.palate == "-" && a.input == "-") throw usage_error("the palate and the mesh cannot both be standard input");
  const MeshTarget target = mesh_target(a.output, a.to);
  softobj::Palate pl;
  try {
    pl = softobj::decode_palate(read_input(a.palate));
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), a.palate));
  }
  const formats::Input in = formats::load_input(a.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("the input is {}, not a mesh ({})", formats::format_name(in.format), in.name);
  const Mesh poly = formats::parse(in, formats::read_mesh);
  if (const auto skipped = formats::skipped_faces(poly))
    throw bad_input("{} faces of the mesh are not manifold and would be lost ({})", skipped, in.name);
  TriMesh m;
  m.request_vertex_normals();
  std::vector<TriMesh::VertexHandle> vh;
  for (auto v : poly.vertices()) {
    vh.push_back(m.add_vertex(poly.point(v)));
    if (poly.has_vertex_normals()) m.set_normal(vh.back(), poly.normal(v));
  }
  for (auto f : poly.faces()) {
    std::vector<TriMesh::VertexHandle> c;
    for (auto v : poly.fv_range(f)) c.push_back(vh[static_cast<std::size_t>(v.idx())]);
    if (c.size() != 3) throw bad_input("face {} has {} vertices: palate takes triangle meshes ({})", f.idx(), c.size(), in.name);
    m.add_face(c);
  }
  if (!poly.has_vertex_normals()) {
    m.request_face_normals();
    m.update_normals();
  }
  softobj::palate_pass2(m, pl);
  write_trimesh(m, target);
  return 0;
}

}  // namespace fest::softobj_tool
