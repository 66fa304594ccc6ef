// STL reader and writer, ascii and binary. STL stores every triangle with its own
// three corners; the reader merges corners with exactly equal coordinates into one
// vertex (in order of first appearance) so the mesh has connectivity again, and keeps
// facet normals as face normals. A file is binary when its size is exactly
// 84 + 50 * (triangle count in bytes 80..83): binary headers may begin with "solid"
// too, so the size decides, not the first word.

#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "core/polygon_triangulation.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/mesh_formats.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats::mesh_detail {
namespace {

struct PointKey {
  double x, y, z;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    // +0.0 and -0.0 compare equal, so they must hash alike: add 0.0 (turns -0 into +0).
    auto bits = [](double v) {
      v += 0.0;
      std::uint64_t b;
      std::memcpy(&b, &v, sizeof b);
      return b;
    };
    std::uint64_t h = bits(k.x);
    h = h * 0x9E3779B97F4A7C15ull ^ bits(k.y);
    h = h * 0x9E3779B97F4A7C15ull ^ bits(k.z);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// Collects triangles, merging equal corners, then builds the mesh.
class StlAssembler {
 public:
  void add_triangle(const Mesh::Normal& normal, const PointKey* corners) {
    for (int k = 0; k < 3; ++k) {
      auto [it, inserted] = index_.try_emplace(corners[k], static_cast<std::uint32_t>(points_.size()));
      if (inserted) points_.push_back(corners[k]);
      triangles_.push_back(it->second);
    }
    normals_.push_back(normal);
  }

  Mesh build() {
    Mesh mesh;
    const std::size_t n_faces = normals_.size();
    mesh.reserve(points_.size(), points_.size() + n_faces, n_faces);
    for (const PointKey& p : points_) mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
    mesh.request_face_normals();
    MeshBuilder builder(mesh, "STL");
    for (std::size_t f = 0; f < n_faces; ++f) {
      Mesh::FaceHandle fh = builder.add_face(&triangles_[3 * f], 3, f + 1);
      if (fh.is_valid()) mesh.set_normal(fh, normals_[f]);
    }
    builder.finish();
    return mesh;
  }

 private:
  std::unordered_map<PointKey, std::uint32_t, PointKeyHash> index_;
  std::vector<PointKey> points_;
  std::vector<std::uint32_t> triangles_;
  std::vector<Mesh::Normal> normals_;
};

float read_float_le(const char* p) {
  unsigned char raw[4];
  std::memcpy(raw, p, 4);
  std::uint32_t bits = raw[0] | (raw[1] << 8) | (raw[2] << 16) | (static_cast<std::uint32_t>(raw[3]) << 24);
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

std::uint32_t read_u32_le(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return u[0] | (u[1] << 8) | (u[2] << 16) | (static_cast<std::uint32_t>(u[3]) << 24);
}

void put_u32_le(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

void put_float_le(std::string& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  put_u32_le(out, bits);
}

bool is_binary(std::string_view bytes) {
  return bytes.size() >= 84 && bytes.size() - 84 == 50 * static_cast<std::uint64_t>(read_u32_le(bytes.data() + 80));
}

Mesh read_binary(std::string_view bytes) {
  const std::uint32_t n = read_u32_le(bytes.data() + 80);
  if (n > max_element_count) throw bad_input("binary STL: {} triangles are more than fest can hold", n);
  StlAssembler assembler;
  for (std::uint32_t i = 0; i < n; ++i) {
    const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(i);
    Mesh::Normal normal(read_float_le(record), read_float_le(record + 4), read_float_le(record + 8));
    PointKey corners[3];
    for (int k = 0; k < 3; ++k) {
      const char* c = record + 12 + 12 * k;
      corners[k] = {read_float_le(c), read_float_le(c + 4), read_float_le(c + 8)};
    }
    assembler.add_triangle(normal, corners);
  }
  return assembler.build();
}

class AsciiStlParser {
 public:
  explicit AsciiStlParser(std::string_view bytes) : cursor_(bytes) {}

  Mesh parse() {
    if (cursor_.next_token() != "solid")
      throw bad_input("STL: neither binary (size is not 84 + 50 * triangle count) nor ascii (no \"solid\")");
    skip_line();  // the solid's name may contain spaces
    for (;;) {
      std::string_view word = cursor_.next_token();
      if (word == "facet") {
        read_facet();
      } else if (word == "endsolid") {
        skip_line();
        cursor_.skip_whitespace();
        if (cursor_.at_end()) break;
        expect("solid");  // several solids in one file
        skip_line();
      } else if (word.empty()) {
        throw bad_input("ascii STL: file ends without \"endsolid\" (truncated?)");
      } else {
        fail(fmt::format("expected \"facet\" or \"endsolid\", found \"{}\"", fest::quoted_bytes(word, 32)));
      }
    }
    return assembler_.build();
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw bad_input("ascii STL line {}: {}", cursor_.line_number(), what);
  }
  void expect(std::string_view word) {
    std::string_view got = cursor_.next_token();
    if (got != word) fail(fmt::format("expected \"{}\", found \"{}\"", word, fest::quoted_bytes(got, 32)));
  }
  double number() {
    std::string_view token = cursor_.next_token();
    double v;
    if (!parse_double(token, v)) fail(fmt::format("\"{}\" is not a number", fest::quoted_bytes(token, 32)));
    return v;
  }
  void skip_line() {
    std::string_view ignored;
    cursor_.next_line(ignored);
  }
  void read_facet() {
    expect("normal");
    Mesh::Normal normal;
    for (int k = 0; k < 3; ++k) normal[k] = number();
    expect("outer");
    expect("loop");
    PointKey corners[3];
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      corners[k].x = number();
      corners[k].y = number();
      corners[k].z = number();
    }
    expect("endloop");
    expect("endfacet");
    assembler_.add_triangle(normal, corners);
  }

  TextCursor cursor_;
  StlAssembler assembler_;
};

// A facet normal: the file's face normal when the mesh has them, else computed.
Mesh::Normal facet_normal(const Mesh& mesh, Mesh::FaceHandle f, const Mesh::Point& a, const Mesh::Point& b,
                          const Mesh::Point& c, bool use_face_normal) {
  if (use_face_normal) return mesh.normal(f);
  Mesh::Normal n = (b - a) % (c - a);
  double length = n.norm();
  return length > 0 ? Mesh::Normal(n / length) : Mesh::Normal(0, 0, 0);
}

}  // namespace

Mesh read_stl(std::string_view bytes) {
  const bool binary = is_binary(bytes);
  Mesh mesh = binary ? read_binary(bytes) : AsciiStlParser(bytes).parse();
  set_point_storage(mesh, binary ? CoordinateStorage::float32 : CoordinateStorage::decimal);
  return mesh;
}

std::string write_stl(const Mesh& input, bool ascii) {
  std::optional<Mesh> storage;
  const Mesh& mesh = compacted(input, storage);
  // STL holds triangles only: a polygon is written as a fan around its first vertex,
  // a concave one as ears (core/polygon_triangulation.hpp); n - 2 triangles either way.
  const FacesBeside extra = extra_faces_to_write(mesh);
  std::size_t n_triangles = 0;
  for (auto f : mesh.faces()) n_triangles += mesh.valence(f) - 2;
  for (const auto& face : extra.faces) n_triangles += face.size() >= 3 ? face.size() - 2 : 0;
  if (!ascii && n_triangles > 0xffffffffu) throw bad_input("binary STL: {} triangles exceed its 32-bit count", n_triangles);
  std::string out;
  if (ascii) {
    out = "solid fest\n";
  } else {
    out.assign(80, '\0');
    const char title[] = "binary STL written by fest";
    std::memcpy(out.data(), title, sizeof title - 1);
    put_u32_le(out, static_cast<std::uint32_t>(n_triangles));
    out.reserve(84 + 50 * n_triangles);
  }
  std::vector<Mesh::Point> corners;
  std::vector<std::array<double, 3>> positions;
  for_each_written_face(mesh, extra, [&](const std::vector<int>& face, const Mesh::Color*, Mesh::FaceHandle f) {
    corners.clear();
    positions.clear();
    for (int v : face) {
      corners.push_back(mesh.point(Mesh::VertexHandle(v)));
      positions.push_back({corners.back()[0], corners.back()[1], corners.back()[2]});
    }
    const bool use_face_normal = f.is_valid() && mesh.has_face_normals() && corners.size() == 3;
    for (const auto& t : triangulate_polygon(positions)) {
      const Mesh::Point* tri[3] = {&corners[t[0]], &corners[t[1]], &corners[t[2]]};
      Mesh::Normal normal = facet_normal(mesh, f, *tri[0], *tri[1], *tri[2], use_face_normal);
      if (ascii) {
        out += "facet normal";
        for (int j = 0; j < 3; ++j) {
          out.push_back(' ');
          append_number(out, normal[j]);
        }
        out += "\nouter loop\n";
        for (const Mesh::Point* p : tri) {
          out += "vertex";
          for (int j = 0; j < 3; ++j) {
            out.push_back(' ');
            append_number(out, (*p)[j]);
          }
          out.push_back('\n');
        }
        out += "endloop\nendfacet\n";
      } else {
        for (int j = 0; j < 3; ++j) put_float_le(out, narrow_to_float(normal[j]));
        for (const Mesh::Point* p : tri)
          for (int j = 0; j < 3; ++j) put_float_le(out, narrow_to_float((*p)[j]));
        out.append(2, '\0');  // attribute byte count
      }
    }
  });
  if (ascii) out += "endsolid fest\n";
  return out;
}

}  // namespace fest::formats::mesh_detail
