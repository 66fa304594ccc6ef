#include "formats/mesh/triangle_soup.hpp"

#include <utility>

#include "formats/mesh/mesh_io.hpp"

namespace fest::formats {

namespace {

void append_fan(std::vector<std::array<int, 3>>& out, const std::vector<int>& polygon) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) out.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

}  // namespace

TriangleSoup to_triangle_soup(const Mesh& mesh) {
  TriangleSoup soup;
  soup.positions.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    soup.positions.push_back({p[0], p[1], p[2]});
  }
  std::vector<int> polygon;
  for (auto f : mesh.faces()) {
    polygon.clear();
    for (auto v : mesh.fv_range(f)) polygon.push_back(v.idx());
    append_fan(soup.triangles, polygon);
  }
  for (const auto& face : skipped_face_list(mesh)) append_fan(soup.triangles, face);
  for (auto v : mesh.vertices()) {
    if (mesh.has_vertex_normals()) soup.normals.push_back({mesh.normal(v)[0], mesh.normal(v)[1], mesh.normal(v)[2]});
    if (mesh.has_vertex_colors()) soup.colors.push_back({mesh.color(v)[0], mesh.color(v)[1], mesh.color(v)[2]});
    if (mesh.has_vertex_texcoords2D())
      soup.texcoords.push_back({mesh.texcoord2D(v)[0], mesh.texcoord2D(v)[1]});
  }
  return soup;
}

Mesh to_mesh(const TriangleSoup& soup) {
  Mesh mesh;
  for (const auto& p : soup.positions) mesh.add_vertex(Mesh::Point(p[0], p[1], p[2]));
  if (!soup.normals.empty()) mesh.request_vertex_normals();
  if (!soup.colors.empty()) mesh.request_vertex_colors();
  if (!soup.texcoords.empty()) mesh.request_vertex_texcoords2D();
  for (auto v : mesh.vertices()) {
    const auto i = static_cast<std::size_t>(v.idx());
    if (!soup.normals.empty()) mesh.set_normal(v, Mesh::Normal(soup.normals[i][0], soup.normals[i][1], soup.normals[i][2]));
    if (!soup.colors.empty()) mesh.set_color(v, Mesh::Color(soup.colors[i][0], soup.colors[i][1], soup.colors[i][2]));
    if (!soup.texcoords.empty())
      mesh.set_texcoord2D(v, Mesh::TexCoord2D(static_cast<float>(soup.texcoords[i][0]), static_cast<float>(soup.texcoords[i][1])));
  }
  std::vector<std::vector<int>> extra;
  std::vector<Mesh::VertexHandle> handles(3);
  for (const auto& t : soup.triangles) {
    for (int k = 0; k < 3; ++k) handles[static_cast<std::size_t>(k)] = Mesh::VertexHandle(t[static_cast<std::size_t>(k)]);
    if (!mesh.add_face(handles).is_valid()) extra.push_back({t[0], t[1], t[2]});
  }
  if (!extra.empty()) set_extra_faces(mesh, std::move(extra));
  return mesh;
}

}  // namespace fest::formats
