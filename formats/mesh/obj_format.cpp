// Wavefront OBJ reader and writer: v (optionally "x y z r g b", colours 0..1), vt, vn,
// f with every index form (v, v/t, v//n, v/t/n; negative = relative to the vertices so
// far), l (polylines) and p (points), kept as line and point elements (mesh_io.hpp).
// Other statements (o, g, s, usemtl, mtllib ...) are ignored. OBJ gives normals and
// texture coordinates per face corner; fest::Mesh keeps them per vertex, taken from the
// first corner that names the vertex; corners that name other values are counted as not
// kept (unread_parts()). When no corner names a normal and there is one vn per v
// (MeshLab's point clouds), the normals are the vertices' in order.

#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats::mesh_detail {
namespace {

constexpr std::int32_t no_index = -1;

struct Corner {
  std::int32_t vertex;
  std::int32_t texcoord;
  std::int32_t normal;
};

// Resolves a 1-based (or negative, relative) OBJ index to 0-based; `count` is how many
// items were defined before this line.
std::int32_t resolve(std::string_view token, std::size_t count, std::size_t line) {
  std::int64_t index = 0;
  if (!parse_int64(token, index) || index == 0)
    throw bad_input("OBJ line {}: \"{}\" is not a valid index (indices start at 1)", line, fest::quoted_bytes(token, 32));
  if (index < 0) index += static_cast<std::int64_t>(count);
  else index -= 1;
  if (index < 0 || index >= static_cast<std::int64_t>(max_element_count))
    throw bad_input("OBJ line {}: index \"{}\" is out of range", line, fest::quoted_bytes(token, 32));
  return static_cast<std::int32_t>(index);
}

Corner parse_corner(std::string_view token, std::size_t n_v, std::size_t n_vt, std::size_t n_vn, std::size_t line) {
  Corner corner{no_index, no_index, no_index};
  std::size_t slash1 = token.find('/');
  corner.vertex = resolve(token.substr(0, slash1), n_v, line);
  if (slash1 == std::string_view::npos) return corner;
  std::string_view rest = token.substr(slash1 + 1);
  std::size_t slash2 = rest.find('/');
  std::string_view texcoord = rest.substr(0, slash2);
  if (!texcoord.empty()) corner.texcoord = resolve(texcoord, n_vt, line);
  if (slash2 != std::string_view::npos) corner.normal = resolve(rest.substr(slash2 + 1), n_vn, line);
  return corner;
}

}  // namespace

Mesh read_obj(std::string_view bytes) {
  TextCursor cursor(bytes);
  Mesh mesh;
  std::vector<Mesh::Normal> normals;
  std::vector<Mesh::TexCoord2D> texcoords;
  std::vector<Corner> corners;
  std::vector<std::size_t> face_offsets{0};
  std::vector<std::string_view> tokens;
  std::vector<std::vector<int>> lines, points;
  std::vector<std::size_t> line_numbers, point_numbers;  // where each element was, for messages
  std::string_view line;
  std::size_t line_number = 0;
  while (cursor.next_line(line)) {
    ++line_number;
    tokens.clear();
    LineTokens split(strip_comment(line));
    for (std::string_view t = split.next(); !t.empty(); t = split.next()) tokens.push_back(t);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    auto numbers = [&](std::size_t count, double* out) {
      if (tokens.size() < count + 1) throw bad_input("OBJ line {}: {} needs {} numbers", line_number, keyword, count);
      for (std::size_t k = 0; k < count; ++k)
        if (!parse_double(tokens[k + 1], out[k]))
          throw bad_input("OBJ line {}: \"{}\" is not a number", line_number, fest::quoted_bytes(tokens[k + 1], 32));
    };
    if (keyword == "v") {
      double v[6];
      const bool colored = tokens.size() >= 7;
      numbers(colored ? 6 : 3, v);
      if (mesh.n_vertices() >= max_element_count) throw bad_input("OBJ: more vertices than fest can hold");
      Mesh::VertexHandle vh = mesh.add_vertex(Mesh::Point(v[0], v[1], v[2]));
      if (colored && !mesh.has_vertex_colors()) {
        // Vertices before the first coloured one get white (OpenMesh leaves new
        // property values uninitialised).
        mesh.request_vertex_colors();
        for (auto earlier : mesh.vertices()) mesh.set_color(earlier, Mesh::Color(255, 255, 255));
      }
      if (colored) mesh.set_color(vh, Mesh::Color(color_from_unit(v[3]), color_from_unit(v[4]), color_from_unit(v[5])));
      else if (mesh.has_vertex_colors()) mesh.set_color(vh, Mesh::Color(255, 255, 255));
    } else if (keyword == "vn") {
      double n[3];
      numbers(3, n);
      normals.emplace_back(n[0], n[1], n[2]);
    } else if (keyword == "vt") {
      double t[2] = {0, 0};
      numbers(tokens.size() >= 3 ? 2 : 1, t);
      texcoords.emplace_back(narrow_to_float(t[0]), narrow_to_float(t[1]));
    } else if (keyword == "f" || keyword == "fo") {
      for (std::size_t k = 1; k < tokens.size(); ++k)
        corners.push_back(parse_corner(tokens[k], mesh.n_vertices(), texcoords.size(), normals.size(), line_number));
      face_offsets.push_back(corners.size());
    } else if (keyword == "l" || keyword == "p") {
      // Only the vertex part of "v/t" counts: an element's texture coordinates are not kept.
      std::vector<int> element;
      for (std::size_t k = 1; k < tokens.size(); ++k)
        element.push_back(resolve(tokens[k].substr(0, tokens[k].find('/')), mesh.n_vertices(), line_number));
      (keyword == "l" ? lines : points).push_back(std::move(element));
      (keyword == "l" ? line_numbers : point_numbers).push_back(line_number);
    }
  }
  if (mesh.n_vertices() == 0 && face_offsets.size() == 1) throw bad_input("OBJ: no vertices or faces found");
  for (const auto& [elements, numbers] : {std::pair{&lines, &line_numbers}, std::pair{&points, &point_numbers}})
    for (std::size_t k = 0; k < elements->size(); ++k)
      for (int v : (*elements)[k])
        if (static_cast<std::size_t>(v) >= mesh.n_vertices())
          throw bad_input("OBJ line {}: vertex index {} is out of range (the file has {} vertices)", (*numbers)[k],
                          v + 1, mesh.n_vertices());

  // Indices can only be checked now: a positive index may name a later vertex.
  const std::size_t n_faces = face_offsets.size() - 1;
  bool any_normal = false, any_texcoord = false;
  for (std::size_t f = 0; f < n_faces; ++f)
    for (std::size_t c = face_offsets[f]; c < face_offsets[f + 1]; ++c) {
      const Corner& corner = corners[c];
      if (static_cast<std::size_t>(corner.vertex) >= mesh.n_vertices() ||
          (corner.texcoord != no_index && static_cast<std::size_t>(corner.texcoord) >= texcoords.size()) ||
          (corner.normal != no_index && static_cast<std::size_t>(corner.normal) >= normals.size()))
        throw bad_input("OBJ face {}: index out of range (the file has {} vertices, {} texture coordinates, {} normals)",
                        f + 1, mesh.n_vertices(), texcoords.size(), normals.size());
      any_normal = any_normal || corner.normal != no_index;
      any_texcoord = any_texcoord || corner.texcoord != no_index;
    }
  // A point cloud (MeshLab writes one vn per v and no faces): no corner names the
  // normals, which belong to the vertices in order.
  const bool normal_per_vertex = !any_normal && !normals.empty() && normals.size() == mesh.n_vertices();
  if (any_normal || normal_per_vertex) mesh.request_vertex_normals();
  if (any_texcoord) mesh.request_vertex_texcoords2D();
  std::vector<bool> has_normal(any_normal ? mesh.n_vertices() : 0), has_texcoord(any_texcoord ? mesh.n_vertices() : 0);
  for (auto v : mesh.vertices()) {
    if (any_normal) mesh.set_normal(v, Mesh::Normal(0, 0, 0));
    if (any_texcoord) mesh.set_texcoord2D(v, Mesh::TexCoord2D(0, 0));
  }
  if (normal_per_vertex)
    for (auto v : mesh.vertices()) mesh.set_normal(v, normals[static_cast<std::size_t>(v.idx())]);
  // Corners whose normal or texture coordinates differ from the ones their vertex got
  // (hard edges, texture seams) are not kept: counted, for unread_parts().
  std::size_t other_normals = 0, other_texcoords = 0;
  for (const Corner& corner : corners) {
    Mesh::VertexHandle vh(corner.vertex);
    if (corner.normal != no_index) {
      if (!has_normal[corner.vertex]) {
        has_normal[corner.vertex] = true;
        mesh.set_normal(vh, normals[corner.normal]);
      } else if (mesh.normal(vh) != normals[corner.normal]) {
        ++other_normals;
      }
    }
    if (corner.texcoord != no_index) {
      if (!has_texcoord[corner.vertex]) {
        has_texcoord[corner.vertex] = true;
        mesh.set_texcoord2D(vh, texcoords[corner.texcoord]);
      } else if (mesh.texcoord2D(vh) != texcoords[corner.texcoord]) {
        ++other_texcoords;
      }
    }
  }
  std::vector<MeshPart> not_kept;
  if (other_normals > 0)
    not_kept.push_back({"face corners' normals that differ from their vertex's (OBJ vn per corner)", other_normals});
  if (other_texcoords > 0)
    not_kept.push_back(
        {"face corners' texture coordinates that differ from their vertex's (OBJ vt per corner)", other_texcoords});
  if (!not_kept.empty()) set_unread_parts(mesh, std::move(not_kept));

  MeshBuilder builder(mesh, "OBJ");
  std::vector<std::uint32_t> indices;
  mesh.reserve(mesh.n_vertices(), mesh.n_vertices() + n_faces, n_faces);
  for (std::size_t f = 0; f < n_faces; ++f) {
    indices.clear();
    for (std::size_t c = face_offsets[f]; c < face_offsets[f + 1]; ++c)
      indices.push_back(static_cast<std::uint32_t>(corners[c].vertex));
    builder.add_face(indices.data(), indices.size(), f + 1);
  }
  builder.finish();
  if (!lines.empty()) set_line_elements(mesh, std::move(lines));
  if (!points.empty()) set_point_elements(mesh, std::move(points));
  set_decimal_storage(mesh);
  return mesh;
}

std::string write_obj(const Mesh& input) {
  const MeshToWrite written(input);
  const Mesh& mesh = written.mesh;
  const bool normals = written.normals, colors = written.colors, texcoords = written.texcoords;
  std::string out = "# written by fest\n";
  out.reserve(mesh.n_vertices() * 40 + mesh.n_faces() * 24 + 32);
  for (auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    out += "v";
    append_coordinates(out, p, 3);
    if (colors)  // colour / 255 in shortest form reads back as the same byte
      for (int k = 0; k < 3; ++k) {
        out.push_back(' ');
        append_number(out, mesh.color(v)[k] / 255.0);
      }
    out.push_back('\n');
  }
  if (texcoords)
    for (auto v : mesh.vertices()) {
      out += "vt";
      append_coordinates(out, mesh.texcoord2D(v), 2);
      out.push_back('\n');
    }
  if (normals)
    for (auto v : mesh.vertices()) {
      out += "vn";
      append_coordinates(out, mesh.normal(v), 3);
      out.push_back('\n');
    }
  for_each_written_face(mesh, extra_faces_to_write(mesh), [&](const std::vector<int>& face, const Mesh::Color*,
                                                               Mesh::FaceHandle) {
    out.push_back('f');
    for (int v : face) {
      const int i = v + 1;
      if (texcoords && normals) fmt::format_to(std::back_inserter(out), " {0}/{0}/{0}", i);
      else if (texcoords) fmt::format_to(std::back_inserter(out), " {0}/{0}", i);
      else if (normals) fmt::format_to(std::back_inserter(out), " {0}//{0}", i);
      else fmt::format_to(std::back_inserter(out), " {}", i);
    }
    out.push_back('\n');
  });
  // Line and point elements name vertices only (their texture coordinates, if any,
  // are the vertices' own).
  for (const auto& [keyword, elements] : {std::pair{'l', line_elements(mesh)}, std::pair{'p', point_elements(mesh)}})
    for (const auto& element : elements) {
      out.push_back(keyword);
      for (int v : element) fmt::format_to(std::back_inserter(out), " {}", v + 1);
      out.push_back('\n');
    }
  return out;
}

}  // namespace fest::formats::mesh_detail
