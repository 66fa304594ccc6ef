#include "surface_io.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "formats/input.hpp"
#include "formats/mesh/indexed_ply.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::isosurf_tool {

std::string output_format(const std::string& to, const std::string& output) {
  std::string f = to;
  if (f.empty() && output != "-" && !output.empty()) {
    const auto dot = output.rfind('.');
    if (dot == std::string::npos) throw usage_error("cannot tell the mesh format of '{}': add --to", output);
    f = output.substr(dot + 1);
  }
  if (f.empty()) f = "ply";
  for (const char* ok : {"ply", "plya", "obj", "off", "stl", "drc"})
    if (f == ok) return f;
  throw usage_error("mesh format '{}' (ply, plya, obj, off, stl or drc expected)", f);
}

std::string encode_surface(const isosurface::Surface& s, const std::string& format, int draco_bits) {
  const bool normals = s.normals.size() == s.xyz.size() && !s.normals.empty();
  if (format == "ply" && !normals) return formats::write_indexed_ply(s.xyz, s.triangles);
  Mesh mesh;
  if (normals) mesh.request_vertex_normals();
  std::vector<Mesh::VertexHandle> vh(s.vertices());
  for (std::size_t v = 0; v < s.vertices(); ++v) {
    vh[v] = mesh.add_vertex(Mesh::Point(s.xyz[3 * v], s.xyz[3 * v + 1], s.xyz[3 * v + 2]));
    if (normals) mesh.set_normal(vh[v], Mesh::Normal(s.normals[3 * v], s.normals[3 * v + 1], s.normals[3 * v + 2]));
  }
  std::vector<std::vector<int>> extra;
  for (const auto& t : s.triangles) {
    const auto f = mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    if (!f.is_valid()) extra.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  }
  if (!extra.empty()) {
    if (format == "drc" || format == "stl")
      throw bad_input("{} triangles are non-manifold and cannot be stored as {}; use ply, obj or off", extra.size(), format);
    formats::set_extra_faces(mesh, std::move(extra));
  }
  formats::MeshWriteOptions wo;
  formats::Format f = formats::Format::ply;
  if (format == "plya") wo.ascii = true;
  else if (format == "obj") f = formats::Format::obj;
  else if (format == "off") f = formats::Format::off;
  else if (format == "stl") f = formats::Format::stl;
  else if (format == "drc") f = formats::Format::drc, wo.draco_position_bits = draco_bits;
  return formats::write_mesh(mesh, f, wo);
}

isosurface::Surface decode_surface(const std::string& path, std::size_t& fanned) {
  formats::Input in = formats::load_input(path);
  if (in.bytes.empty()) throw bad_input("empty input ({})", input_name(path));
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("expected a mesh, got {} ({})", formats::format_name(in.format), in.name);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  isosurface::Surface s;
  s.xyz.reserve(3 * mesh.n_vertices());
  for (const auto& vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    for (int c = 0; c < 3; ++c) s.xyz.push_back(static_cast<float>(p[c]));
  }
  fanned = 0;
  auto add = [&](const std::vector<int>& poly) {
    if (poly.size() < 3) return;
    if (poly.size() > 3) ++fanned;
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      s.triangles.push_back({static_cast<std::uint32_t>(poly[0]), static_cast<std::uint32_t>(poly[k]),
                             static_cast<std::uint32_t>(poly[k + 1])});
  };
  std::vector<int> poly;
  for (const auto& fh : mesh.faces()) {
    poly.clear();
    for (const auto& v : mesh.fv_range(fh)) poly.push_back(v.idx());
    add(poly);
  }
  for (const auto& f : formats::skipped_face_list(mesh)) add(f);
  return s;
}

nlohmann::json stats_json(const isosurface::MeshStats& m) {
  return {{"vertices", m.vertices},
          {"unreferenced_vertices", m.unreferenced_vertices},
          {"triangles", m.triangles},
          {"degenerate_triangles", m.degenerate_triangles},
          {"edges", m.edges},
          {"boundary_edges", m.boundary_edges},
          {"nonmanifold_edges", m.nonmanifold_edges},
          {"nonmanifold_vertices", m.nonmanifold_vertices},
          {"orientation_conflicts", m.orientation_conflicts},
          {"components", m.components},
          {"euler", m.euler},
          {"genus", m.genus < 0 ? nlohmann::json(nullptr) : nlohmann::json(m.genus)},
          {"closed", m.closed},
          {"area", m.area},
          {"volume", m.volume}};
}

}  // namespace fest::isosurf_tool
