// OFF reader and writer. Header keyword [ST][C][N]OFF (Geomview's order: ST texture
// coordinates, C colours, N normals); each vertex line is "x y z [nx ny nz] [r g b [a]]
// [s t]" and each face line "n i0 .. in-1 [r g b [a]]". Colours given as integers are
// 0..255, as decimals 0..1 (Geomview). The file is read line by line, as OFF's
// optional per-line fields require; '#' starts a comment.

#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats::mesh_detail {
namespace {

// The next line with something on it (comments stripped), split into tokens.
class OffLines {
 public:
  explicit OffLines(std::string_view text) : cursor_(text) {}

  bool next(std::vector<std::string_view>& tokens) {
    std::string_view line;
    while (cursor_.next_line(line)) {
      ++line_number_;
      tokens.clear();
      LineTokens split(strip_comment(line));
      for (std::string_view t = split.next(); !t.empty(); t = split.next()) tokens.push_back(t);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  std::size_t line_number() const { return line_number_; }
  std::size_t remaining() const { return cursor_.remaining(); }

 private:
  TextCursor cursor_;
  std::size_t line_number_ = 0;
};

struct OffKind {
  bool texcoords = false;
  bool colors = false;
  bool normals = false;
};

OffKind parse_keyword(std::string_view keyword) {
  constexpr std::string_view off = "OFF";
  if (keyword.size() < off.size() || keyword.substr(keyword.size() - off.size()) != off)
    throw bad_input("OFF: first keyword \"{}\" is not [ST][C][N]OFF", fest::quoted_bytes(keyword, 32));
  std::string_view prefix = keyword.substr(0, keyword.size() - off.size());
  OffKind kind;
  auto take = [&](std::string_view p) {
    if (prefix.substr(0, p.size()) != p) return false;
    prefix.remove_prefix(p.size());
    return true;
  };
  kind.texcoords = take("ST");
  kind.colors = take("C");
  kind.normals = take("N");
  if (take("4") || take("n")) throw bad_input("OFF: {} (4D or n-dimensional OFF) is not supported", keyword);
  if (!prefix.empty()) throw bad_input("OFF: first keyword \"{}\" is not [ST][C][N]OFF", fest::quoted_bytes(keyword, 32));
  return kind;
}

// r g b [a]: integers mean 0..255, decimals 0..1.
bool parse_color(const std::string_view* tokens, Mesh::Color& color) {
  bool integers = true;
  for (int k = 0; k < 3; ++k) integers = integers && is_integer_literal(tokens[k]);
  for (int k = 0; k < 3; ++k) {
    double v;
    if (!parse_double(tokens[k], v)) return false;
    color[k] = integers ? color_from_byte_range(v) : color_from_unit(v);
  }
  return true;
}

}  // namespace

Mesh read_off(std::string_view bytes) {
  OffLines lines(bytes);
  std::vector<std::string_view> tokens;
  if (!lines.next(tokens)) throw bad_input("OFF: no header");
  const OffKind kind = parse_keyword(tokens[0]);
  if (tokens.size() > 1 && tokens[1] == "BINARY") throw bad_input("OFF: binary OFF is not supported");
  // The counts follow the keyword on the same line or on the next one.
  if (tokens.size() > 1) tokens.erase(tokens.begin());
  else if (!lines.next(tokens)) throw bad_input("OFF: header ends before the vertex and face counts");
  std::uint64_t n_vertices = 0, n_faces = 0;
  if (tokens.size() < 2 || !parse_uint64(tokens[0], n_vertices) || !parse_uint64(tokens[1], n_faces))
    throw bad_input("OFF line {}: expected non-negative vertex and face counts", lines.line_number());
  // A vertex line needs at least 6 bytes ("0 0 0\n"), a face line 2.
  if (n_vertices > max_element_count || n_faces > max_element_count ||
      n_vertices * 6 + n_faces * 2 > lines.remaining() + 1)
    throw bad_input("OFF header: {} vertices and {} faces exceed what the {} remaining bytes can hold", n_vertices,
                    n_faces, lines.remaining());

  Mesh mesh;
  if (kind.normals) mesh.request_vertex_normals();
  if (kind.colors) mesh.request_vertex_colors();
  if (kind.texcoords) mesh.request_vertex_texcoords2D();
  mesh.reserve(n_vertices, n_vertices + n_faces, n_faces);
  const std::size_t fixed = 3 + (kind.normals ? 3 : 0) + (kind.texcoords ? 2 : 0);
  for (std::uint64_t i = 0; i < n_vertices; ++i) {
    if (!lines.next(tokens)) throw bad_input("OFF: file ends after {} of {} vertices", i, n_vertices);
    const std::size_t color_count = tokens.size() >= fixed ? tokens.size() - fixed : 0;
    if (tokens.size() < fixed || (kind.colors && color_count != 3 && color_count != 4))
      throw bad_input("OFF line {}: vertex {} has {} values, which does not fit the {}OFF header",
                      lines.line_number(), i + 1, tokens.size(), kind.colors ? "C" : "");
    double values[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    std::size_t t = 0;
    auto number = [&](double& out) {
      if (!parse_double(tokens[t], out))
        throw bad_input("OFF line {}: \"{}\" is not a number", lines.line_number(), fest::quoted_bytes(tokens[t], 32));
      ++t;
    };
    for (int k = 0; k < 3; ++k) number(values[k]);
    Mesh::VertexHandle vh = mesh.add_vertex(Mesh::Point(values[0], values[1], values[2]));
    if (kind.normals) {
      for (int k = 3; k < 6; ++k) number(values[k]);
      mesh.set_normal(vh, Mesh::Normal(values[3], values[4], values[5]));
    }
    if (kind.colors) {
      Mesh::Color color;
      if (!parse_color(&tokens[t], color))
        throw bad_input("OFF line {}: vertex {} has a colour that is not numbers", lines.line_number(), i + 1);
      mesh.set_color(vh, color);
      t += color_count;
    }
    if (kind.texcoords) {
      number(values[6]);
      number(values[7]);
      mesh.set_texcoord2D(vh, Mesh::TexCoord2D(narrow_to_float(values[6]), narrow_to_float(values[7])));
    }
  }

  MeshBuilder builder(mesh, "OFF");
  std::vector<std::uint32_t> indices;
  for (std::uint64_t f = 0; f < n_faces; ++f) {
    if (!lines.next(tokens)) throw bad_input("OFF: file ends after {} of {} faces", f, n_faces);
    std::uint64_t n = 0;
    if (!parse_uint64(tokens[0], n) || n > tokens.size() - 1)
      throw bad_input("OFF line {}: face {} should start with its vertex count and list that many indices",
                      lines.line_number(), f + 1);
    indices.clear();
    for (std::size_t k = 1; k <= n; ++k) {
      std::int64_t index = 0;
      if (!parse_int64(tokens[k], index) || index < 0 || static_cast<std::uint64_t>(index) >= n_vertices)
        throw bad_input("OFF line {}: face {} has vertex index \"{}\", outside 0..{}", lines.line_number(), f + 1,
                        fest::quoted_bytes(tokens[k], 32), n_vertices == 0 ? 0 : n_vertices - 1);
      indices.push_back(static_cast<std::uint32_t>(index));
    }
    const std::size_t extra = tokens.size() - 1 - n;
    Mesh::Color color(255, 255, 255);
    const bool colored = extra == 3 || extra == 4;
    if (colored && !parse_color(&tokens[1 + n], color))
      throw bad_input("OFF line {}: face {} has a colour that is not numbers", lines.line_number(), f + 1);
    if (colored && !mesh.has_face_colors()) {
      // Faces listed before the first coloured one get white (OpenMesh leaves new
      // property values uninitialised).
      mesh.request_face_colors();
      for (auto earlier : mesh.faces()) mesh.set_color(earlier, Mesh::Color(255, 255, 255));
    }
    Mesh::FaceHandle fh = builder.add_face(indices.data(), indices.size(), f + 1, &color);
    if (mesh.has_face_colors() && fh.is_valid()) mesh.set_color(fh, color);
  }
  builder.finish();
  set_decimal_storage(mesh);
  return mesh;
}

std::string write_off(const Mesh& input) {
  const MeshToWrite written(input);
  const Mesh& mesh = written.mesh;
  const bool normals = written.normals, colors = written.colors, texcoords = written.texcoords;
  const FacesBeside extra = extra_faces_to_write(mesh);
  std::string out;
  out.reserve(mesh.n_vertices() * 40 + mesh.n_faces() * 20 + 32);
  fmt::format_to(std::back_inserter(out), "{}{}{}OFF\n{} {} 0\n", texcoords ? "ST" : "", colors ? "C" : "",
                 normals ? "N" : "", mesh.n_vertices(), mesh.n_faces() + extra.faces.size());
  auto put_color = [&](const Mesh::Color& c) {
    fmt::format_to(std::back_inserter(out), " {} {} {} 255", static_cast<unsigned>(c[0]), static_cast<unsigned>(c[1]),
                   static_cast<unsigned>(c[2]));
  };
  for (auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    append_number(out, p[0]);
    append_coordinates(out, p, 3, 1);
    if (normals) append_coordinates(out, mesh.normal(v), 3);
    if (colors) put_color(mesh.color(v));
    if (texcoords) append_coordinates(out, mesh.texcoord2D(v), 2);
    out.push_back('\n');
  }
  for_each_written_face(mesh, extra, [&](const std::vector<int>& face, const Mesh::Color* color, Mesh::FaceHandle) {
    fmt::format_to(std::back_inserter(out), "{}", face.size());
    for (int v : face) fmt::format_to(std::back_inserter(out), " {}", v);
    if (color) put_color(*color);
    out.push_back('\n');
  });
  return out;
}

}  // namespace fest::formats::mesh_detail
