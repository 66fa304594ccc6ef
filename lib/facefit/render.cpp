#include "facefit/render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace fest::facefit {

Raster rasterise(const Eigen::VectorXd& shape, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                 const std::vector<double>& values, int width, int height, double scale, const Eigen::Vector2d& center) {
  Raster r;
  r.width = width;
  r.height = height;
  const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  r.value.assign(pixels, std::numeric_limits<float>::quiet_NaN());
  r.shading.assign(pixels, 0.0f);
  std::vector<double> depth(pixels, -std::numeric_limits<double>::infinity());
  for (const auto& t : triangles) {
    Eigen::Vector3d p[3], x[3];
    for (int i = 0; i < 3; ++i) {
      x[i] = shape.segment<3>(3 * static_cast<Eigen::Index>(t[static_cast<std::size_t>(i)]));
      p[i] = {scale * x[i].x() + center.x(), -scale * x[i].y() + center.y(), x[i].z()};
    }
    const Eigen::Vector3d normal = (x[1] - x[0]).cross(x[2] - x[0]);
    const double len = normal.norm();
    const float shade = len > 0 ? static_cast<float>(std::abs(normal.z()) / len) : 0.0f;
    const double area = (p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) - (p[2].x() - p[0].x()) * (p[1].y() - p[0].y());
    if (std::abs(area) < 1e-12) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()}))));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()}))));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        // Barycentric coordinates of the pixel centre.
        const double b1 = ((px - p[0].x()) * (p[2].y() - p[0].y()) - (p[2].x() - p[0].x()) * (py - p[0].y())) / area;
        const double b2 = ((p[1].x() - p[0].x()) * (py - p[0].y()) - (px - p[0].x()) * (p[1].y() - p[0].y())) / area;
        const double b0 = 1 - b1 - b2;
        if (b0 < -1e-9 || b1 < -1e-9 || b2 < -1e-9) continue;
        const double z = b0 * p[0].z() + b1 * p[1].z() + b2 * p[2].z();
        const std::size_t i = static_cast<std::size_t>(py) * static_cast<std::size_t>(width) + static_cast<std::size_t>(px);
        if (z <= depth[i]) continue;
        depth[i] = z;
        r.shading[i] = shade;
        if (!values.empty())
          r.value[i] = static_cast<float>(b0 * values[t[0]] + b1 * values[t[1]] + b2 * values[t[2]]);
        else
          r.value[i] = 0.0f;
      }
  }
  return r;
}

std::vector<std::uint8_t> vertex_visibility(const Eigen::VectorXd& image_shape,
                                            const std::vector<std::array<std::uint32_t, 3>>& triangles, int width,
                                            int height, double tolerance) {
  // The rasteriser works in model space with v = −s·y + c; feeding it (u, −v, depth)
  // with s = 1 and c = 0 puts every vertex at its own pixel.
  Eigen::VectorXd flipped = image_shape;
  for (Eigen::Index j = 1; j < flipped.size(); j += 3) flipped(j) = -flipped(j);
  std::vector<double> depth_of(static_cast<std::size_t>(image_shape.size() / 3));
  for (std::size_t j = 0; j < depth_of.size(); ++j) depth_of[j] = image_shape(3 * static_cast<Eigen::Index>(j) + 2);
  const Raster r = rasterise(flipped, triangles, depth_of, width, height, 1.0, Eigen::Vector2d::Zero());
  std::vector<std::uint8_t> visible(depth_of.size(), 0);
  for (std::size_t j = 0; j < visible.size(); ++j) {
    const double u = image_shape(3 * static_cast<Eigen::Index>(j)), v = image_shape(3 * static_cast<Eigen::Index>(j) + 1);
    const long px = std::lround(u), py = std::lround(v);
    if (px < 0 || py < 0 || px >= width || py >= height) continue;
    const float z = r.value[static_cast<std::size_t>(py) * static_cast<std::size_t>(width) + static_cast<std::size_t>(px)];
    visible[j] = std::isnan(z) || depth_of[j] >= z - tolerance ? 1 : 0;
  }
  return visible;
}

}  // namespace fest::facefit
