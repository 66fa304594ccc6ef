#pragma once
// What the mesh pictures of the test and example tooling share (render_mesh,
// render_sheet): meshes read into lib/reflectance's triangle meshes, the z-buffer
// rasteriser's fragments shaded into an OpenCV image, the picture written as PNG.
// render_probes draws flat 2-D probe triangles by painter's order instead (see there).

#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/mesh.hpp"
#include "reflectance/rasterizer.hpp"

namespace fest::test_tools {

// A mesh file of any format fest reads.
Mesh read_mesh_file(const std::string& path);

// The mesh's faces fanned into triangles, its vertices moved by `shift` (when given).
reflectance::TriangleMesh triangles_of(const Mesh& mesh);
reflectance::TriangleMesh triangles_of(const Mesh& mesh, const Eigen::Vector3d& shift);

// Every covered pixel of `image` (the camera's size) set to shade(point, normal) of its
// fragment.
template <class Shade>
void paint_fragments(cv::Mat& image, const reflectance::TriangleMesh& mesh, const reflectance::Fragments& fragments,
                     Shade&& shade) {
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      if (!fragments.covered(x, y)) continue;
      const std::size_t i = fragments.index(x, y);
      image.at<cv::Vec3b>(y, x) = shade(i, reflectance::fragment_point(mesh, fragments, i),
                                        reflectance::fragment_normal(mesh, fragments, i));
    }
}

// The image as PNG at `path` (written atomically; "-" is standard output).
void write_png(const std::string& path, const cv::Mat& image);

}  // namespace fest::test_tools
