#include "mesh_output.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"

namespace fest::softobj_tool {

MeshTarget mesh_target(const std::string& output, const std::string& to) {
  MeshTarget t;
  t.path = output;
  if (to == "plya") {
    t.format = {formats::Format::ply, false};
    t.options.ascii = true;
  } else if (!to.empty()) {
    t.format = formats::output_format_from_name(to);
  } else if (!is_stdio(output)) {
    t.format = formats::output_format_from_path(output);
  } else {
    t.format = {formats::Format::ply, false};
  }
  if (formats::kind_of(t.format.format) != formats::Kind::mesh)
    throw usage_error("output format {} is not a mesh format", formats::format_name(t.format.format));
  return t;
}

void write_trimesh(const TriMesh& tri, const MeshTarget& target) {
  Mesh m;
  m.request_vertex_normals();
  std::vector<Mesh::VertexHandle> vh;
  vh.reserve(tri.n_vertices());
  for (auto v : tri.vertices()) {
    vh.push_back(m.add_vertex(tri.point(v)));
    if (tri.has_vertex_normals()) m.set_normal(vh.back(), tri.normal(v));
  }
  for (auto f : tri.faces()) {
    std::vector<Mesh::VertexHandle> c;
    for (auto v : tri.fv_range(f)) c.push_back(vh[static_cast<std::size_t>(v.idx())]);
    m.add_face(c);
  }
  formats::store_output(target.path, formats::write_mesh(m, target.format.format, target.options), target.format.gzip);
}

}  // namespace fest::softobj_tool
