#include "points_input.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "feshape/xyz_codec.hpp"
#include "formats/gzip.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::feshape_tool {

std::vector<Eigen::Vector3d> read_points(const std::string& path, PointsFormat format) {
  const std::string name = is_stdio(path) ? "-" : path;
  std::string bytes = read_input(path);
  if (formats::is_gzip(bytes)) {
    try {
      bytes = formats::gunzip(bytes);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), name));
    }
  }
  std::vector<Eigen::Vector3d> points;
  auto rows = [&](const std::string& text) {
    try {
      return feshape::decode_points(text);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), name));
    }
  };
  if (format == PointsFormat::xyz) {
    points = rows(bytes);
  } else {
    bool is_mesh = false;
    formats::Input in;
    try {
      in = formats::recognise(bytes, name);
      is_mesh = formats::kind_of(in.format) == formats::Kind::mesh;
    } catch (const Error&) {
      if (format == PointsFormat::mesh) throw;
    }
    if (format == PointsFormat::mesh && !is_mesh) throw bad_input("{}", with_location("not a mesh (PLY, OFF, OBJ, STL)", name));
    if (is_mesh) {
      const Mesh m = formats::parse(in, formats::read_mesh);
      for (const auto v : m.vertices()) points.emplace_back(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
      for (const auto& p : points)
        if (!p.allFinite()) throw bad_input("{}", with_location("a vertex has a non-finite coordinate", name));
    } else {
      points = rows(bytes);
    }
  }
  if (points.size() < 10)
    throw bad_input("{}", with_location(fmt::format("{} points: a fit needs at least 10", points.size()), name));
  return points;
}

}  // namespace fest::feshape_tool
