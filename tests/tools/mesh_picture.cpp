#include "mesh_picture.hpp"

#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::test_tools {
namespace {

template <class Place>
reflectance::TriangleMesh fanned(const Mesh& m, Place&& place) {
  reflectance::TriangleMesh t;
  for (const auto v : m.vertices()) t.vertices.push_back(place(Eigen::Vector3d(m.point(v)[0], m.point(v)[1], m.point(v)[2])));
  for (const auto f : m.faces()) {
    std::vector<std::uint32_t> c;
    for (const auto v : m.fv_range(f)) c.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t i = 1; i + 1 < c.size(); ++i) t.triangles.push_back({c[0], c[i], c[i + 1]});
  }
  return t;
}

}  // namespace

Mesh read_mesh_file(const std::string& path) { return formats::parse(formats::load_input(path), formats::read_mesh); }

reflectance::TriangleMesh triangles_of(const Mesh& mesh) {
  return fanned(mesh, [](const Eigen::Vector3d& p) { return p; });
}

reflectance::TriangleMesh triangles_of(const Mesh& mesh, const Eigen::Vector3d& shift) {
  return fanned(mesh, [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return p + shift; });
}

void write_png(const std::string& path, const cv::Mat& image) {
  std::vector<uchar> png;
  if (!cv::imencode(".png", image, png)) throw runtime_failure("PNG encoding failed");
  write_output(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace fest::test_tools
