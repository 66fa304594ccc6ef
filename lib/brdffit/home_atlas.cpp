#include "brdffit/home_atlas.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::brdffit {

FlatTriangles home_image_projection(const reflectance::TriangleMesh& mesh, const std::vector<ImageView>& views,
                                    const HomeAssignment& home) {
  const std::size_t nt = mesh.triangles.size();
  if (home.image.size() != nt) throw bad_input("{} home images for {} triangles", home.image.size(), nt);
  FlatTriangles flat;
  flat.group.resize(nt);
  flat.corners.resize(nt);
  double world_area = 0, pixel_area = 0;
  bool unseen = false;
  for (std::size_t t = 0; t < nt; ++t) {
    const std::int32_t k = home.image[t];
    if (k < 0) {
      unseen = true;
      continue;
    }
    if (static_cast<std::size_t>(k) >= views.size()) throw bad_input("triangle {} has home image {} of {}", t, k, views.size());
    const reflectance::PinholeCamera& cam = views[static_cast<std::size_t>(k)].camera;
    flat.group[t] = static_cast<std::uint32_t>(k);
    for (std::size_t c = 0; c < 3; ++c)
      flat.corners[t][c] = cam.project_distorted(mesh.vertices[mesh.triangles[t][c]]) + Eigen::Vector2d(0.5, 0.5);
    const auto& a = mesh.vertices[mesh.triangles[t][0]];
    world_area += 0.5 * (mesh.vertices[mesh.triangles[t][1]] - a).cross(mesh.vertices[mesh.triangles[t][2]] - a).norm();
    const Eigen::Vector2d e1 = flat.corners[t][1] - flat.corners[t][0], e2 = flat.corners[t][2] - flat.corners[t][0];
    pixel_area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  if (!(pixel_area > 0)) throw bad_input("no triangle has a home image");
  if (unseen) {
    const FlatTriangles axis = axis_projection(mesh, std::sqrt(world_area / pixel_area));
    for (std::size_t t = 0; t < nt; ++t)
      if (home.image[t] < 0) {
        flat.group[t] = static_cast<std::uint32_t>(views.size()) + axis.group[t];
        flat.corners[t] = axis.corners[t];
      }
  }
  return flat;
}

void sample_home_image(const reflectance::TriangleMesh& mesh, const TexelSurface& texels, const HomeAssignment& home,
                       std::size_t image, const ImageView& view, const cv::Mat& radiance, cv::Mat& atlas_rgb) {
  if (radiance.type() != CV_32FC3 || atlas_rgb.type() != CV_32FC3 || atlas_rgb.cols != texels.width ||
      atlas_rgb.rows != texels.height)
    throw bad_input("home-image sampling needs float RGB images of the atlas' size");
  for (int y = 0; y < texels.height; ++y)
    for (int x = 0; x < texels.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(texels.width) + static_cast<std::size_t>(x);
      const std::int32_t t = texels.triangle[i];
      if (t < 0 || home.image[static_cast<std::size_t>(t)] != static_cast<std::int32_t>(image)) continue;
      const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
      const Eigen::Vector3d& b = texels.bary[i];
      const Eigen::Vector3d p = b[0] * mesh.vertices[tri[0]] + b[1] * mesh.vertices[tri[1]] + b[2] * mesh.vertices[tri[2]];
      const Eigen::Vector2d px = view.camera.project_distorted(p);
      // Bilinear with the border clamped (pixel centres at integer coordinates).
      const double fx = std::clamp(px.x(), 0.0, radiance.cols - 1.0), fy = std::clamp(px.y(), 0.0, radiance.rows - 1.0);
      const int x0 = std::min(static_cast<int>(fx), radiance.cols - 1), y0 = std::min(static_cast<int>(fy), radiance.rows - 1);
      const int x1 = std::min(x0 + 1, radiance.cols - 1), y1 = std::min(y0 + 1, radiance.rows - 1);
      const double ax = fx - x0, ay = fy - y0;
      cv::Vec3f& out = atlas_rgb.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c) {
        const double v = (1 - ay) * ((1 - ax) * radiance.at<cv::Vec3f>(y0, x0)[c] + ax * radiance.at<cv::Vec3f>(y0, x1)[c]) +
                         ay * ((1 - ax) * radiance.at<cv::Vec3f>(y1, x0)[c] + ax * radiance.at<cv::Vec3f>(y1, x1)[c]);
        out[c] = std::isfinite(v) ? static_cast<float>(v) : 0.f;
      }
    }
}

}  // namespace fest::brdffit
