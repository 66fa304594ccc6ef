#include "model_output.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/mesh/attributed_ply.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::feshape_tool {

MeshTarget mesh_target(const std::string& output, const std::string& to) {
  MeshTarget t;
  t.path = output;
  std::string f = to;
  if (f.empty() && !is_stdio(output)) f = formats::format_name(formats::output_format_from_path(output).format);
  if (f.empty()) f = "ply";
  if (f != "ply" && f != "plya" && f != "obj" && f != "off")
    throw usage_error("output format {}: feshape writes ply, plya, obj or off", f);
  t.format = f;
  return t;
}

std::string encode_model(const feshape::Model& m, const MeshTarget& target) {
  const std::vector<Eigen::Vector3d> x = m.node_positions();
  if (target.format == "ply") {
    formats::AttributedPly ply;
    ply.comments.push_back("feshape model level (docs/feshape.md): u v = material coordinates");
    formats::PlyColumn cx{"x", "double", {}}, cy{"y", "double", {}}, cz{"z", "double", {}};
    formats::PlyColumn cu{"u", "double", m.mesh.u}, cv{"v", "double", m.mesh.v};
    for (const auto& p : x) {
      cx.values.push_back(p.x());
      cy.values.push_back(p.y());
      cz.values.push_back(p.z());
    }
    ply.vertex = {cx, cy, cz, cu, cv};
    formats::PlyColumn level{"level", "uchar", {}};
    for (std::size_t f = 0; f < m.mesh.elements(); ++f) {
      const auto& t = m.mesh.tris[f];
      ply.faces.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]), static_cast<std::uint32_t>(t[2])});
      level.values.push_back(m.mesh.level[f]);
    }
    ply.face = {level};
    return formats::write_attributed_ply(ply);
  }
  Mesh mesh;
  std::vector<Mesh::VertexHandle> vh;
  for (const auto& p : x) vh.push_back(mesh.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
  for (const auto& t : m.mesh.tris) mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
  formats::MeshWriteOptions o;
  o.ascii = target.format == "plya";
  o.precision = formats::CoordinatePrecision::float64;
  const formats::Format f = target.format == "obj" ? formats::Format::obj
                            : target.format == "off" ? formats::Format::off
                                                     : formats::Format::ply;
  return formats::write_mesh(mesh, f, o);
}

}  // namespace fest::feshape_tool
