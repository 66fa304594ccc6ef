#include "brdffit/texture_bake.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace fest::brdffit {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The point of triangle c closest to p, as barycentric coordinates; returns the distance.
double closest_point(const std::array<Eigen::Vector2d, 3>& c, const Eigen::Vector2d& p, Eigen::Vector3d& bary) {
  const double area = cross2(c[1] - c[0], c[2] - c[0]);
  if (std::abs(area) > 1e-12) {
    const double b1 = cross2(c[2] - c[0], p - c[0]) / -area;  // weight of c[1]
    const double b2 = cross2(c[1] - c[0], p - c[0]) / area;   // weight of c[2]
    const double b0 = 1 - b1 - b2;
    if (b0 >= 0 && b1 >= 0 && b2 >= 0) {
      bary = {b0, b1, b2};
      return 0;
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const std::size_t i = static_cast<std::size_t>(k), j = static_cast<std::size_t>((k + 1) % 3);
    const Eigen::Vector2d e = c[j] - c[i];
    const double len2 = e.squaredNorm();
    const double s = len2 > 0 ? std::clamp((p - c[i]).dot(e) / len2, 0.0, 1.0) : 0.0;
    const double d = (c[i] + s * e - p).norm();
    if (d < best) {
      best = d;
      bary = Eigen::Vector3d::Zero();
      bary[static_cast<Eigen::Index>(i)] = 1 - s;
      bary[static_cast<Eigen::Index>(j)] += s;
    }
  }
  return best;
}

Eigen::Vector3d any_perpendicular(const Eigen::Vector3d& n) {
  const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(a).normalized();
}

}  // namespace

TexelSurface texel_surface(const TextureAtlas& atlas) {
  TexelSurface s;
  s.width = atlas.width;
  s.height = atlas.height;
  const std::size_t n = static_cast<std::size_t>(atlas.width) * static_cast<std::size_t>(atlas.height);
  s.triangle.assign(n, -1);
  s.bary.assign(n, Eigen::Vector3d::Zero());
  s.distance.assign(n, std::numeric_limits<float>::infinity());
  const double reach = atlas.gutter;
  for (std::size_t t = 0; t < atlas.corners.size(); ++t) {
    const auto& c = atlas.corners[t];
    const AtlasChart& chart = atlas.charts[atlas.triangle_chart[t]];
    const double lo_x = std::min({c[0].x(), c[1].x(), c[2].x()}) - reach, hi_x = std::max({c[0].x(), c[1].x(), c[2].x()}) + reach;
    const double lo_y = std::min({c[0].y(), c[1].y(), c[2].y()}) - reach, hi_y = std::max({c[0].y(), c[1].y(), c[2].y()}) + reach;
    // Only the chart's own rectangle: charts never write into each other's gutters.
    const int x0 = std::max(chart.x, static_cast<int>(std::floor(lo_x - 0.5)));
    const int x1 = std::min(chart.x + chart.width - 1, static_cast<int>(std::ceil(hi_x)));
    const int y0 = std::max(chart.y, static_cast<int>(std::floor(lo_y - 0.5)));
    const int y1 = std::min(chart.y + chart.height - 1, static_cast<int>(std::ceil(hi_y)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        const double d = closest_point(c, Eigen::Vector2d(x + 0.5, y + 0.5), b);
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(atlas.width) + static_cast<std::size_t>(x);
        if (d <= reach && d < s.distance[i]) {
          s.distance[i] = static_cast<float>(d);
          s.triangle[i] = static_cast<std::int32_t>(t);
          s.bary[i] = b;
        }
      }
  }
  return s;
}

std::vector<std::array<Eigen::Vector4d, 3>> corner_tangents(const reflectance::TriangleMesh& mesh,
                                                          const TextureAtlas& atlas) {
  std::vector<std::array<Eigen::Vector4d, 3>> out(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d e1 = mesh.vertices[tri[1]] - mesh.vertices[tri[0]];
    const Eigen::Vector3d e2 = mesh.vertices[tri[2]] - mesh.vertices[tri[0]];
    const Eigen::Vector2d d1 = atlas.uv(t, 1) - atlas.uv(t, 0), d2 = atlas.uv(t, 2) - atlas.uv(t, 0);
    const double det = d1.x() * d2.y() - d2.x() * d1.y();
    // dP/du and dP/dv of the triangle's affine map (the standard per-triangle tangent).
    Eigen::Vector3d dpdu = Eigen::Vector3d::Zero(), dpdv = Eigen::Vector3d::Zero();
    if (std::abs(det) > 1e-20) {
      dpdu = (e1 * d2.y() - e2 * d1.y()) / det;
      dpdv = (e2 * d1.x() - e1 * d2.x()) / det;
    }
    for (std::size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d& nrm = mesh.normals[tri[k]];
      Eigen::Vector3d tan = dpdu - nrm * nrm.dot(dpdu);
      tan = tan.norm() > 1e-12 * (1 + dpdu.norm()) ? Eigen::Vector3d(tan.normalized()) : any_perpendicular(nrm);
      const double w = nrm.cross(tan).dot(dpdv) < 0 ? -1.0 : 1.0;
      out[t][k] = Eigen::Vector4d(tan.x(), tan.y(), tan.z(), w);
    }
  }
  return out;
}

PbrMaps bake_pbr(const reflectance::TriangleMesh& mesh, const TextureAtlas& atlas, const TexelSurface& texels,
                 const PbrSurface& surface, int threads) {
  if (texels.width != atlas.width || texels.height != atlas.height)
    throw bad_input("the texel map is {}x{}, the atlas {}x{}", texels.width, texels.height, atlas.width, atlas.height);
  if (mesh.normals.size() != mesh.vertices.size())
    throw bad_input("the mesh has {} normals for {} vertices", mesh.normals.size(), mesh.vertices.size());
  const auto tangents = corner_tangents(mesh, atlas);
  PbrMaps m;
  m.base_color = cv::Mat(atlas.height, atlas.width, CV_32FC3, cv::Scalar(0, 0, 0));
  m.metallic_roughness = cv::Mat(atlas.height, atlas.width, CV_32FC3, cv::Scalar(1, 1, 0));
  m.normal = cv::Mat(atlas.height, atlas.width, CV_32FC3, cv::Scalar(0, 0, 1));
  m.coverage = cv::Mat(atlas.height, atlas.width, CV_8UC1, cv::Scalar(0));
  for_each_chunk(static_cast<std::size_t>(atlas.height), 16, resolve_threads(threads),
                 [&](std::size_t, std::size_t row0, std::size_t row1) {
    for (std::size_t y = row0; y < row1; ++y)
      for (int x = 0; x < atlas.width; ++x) {
        const std::size_t i = y * static_cast<std::size_t>(atlas.width) + static_cast<std::size_t>(x);
        const std::int32_t t = texels.triangle[i];
        if (t < 0) continue;
        const auto tri = static_cast<std::size_t>(t);
        const Eigen::Vector3d& b = texels.bary[i];
        const PbrPoint p = surface(static_cast<std::uint32_t>(t), b);
        const int row = static_cast<int>(y);
        m.coverage.at<std::uint8_t>(row, x) = 255;
        cv::Vec3f& base = m.base_color.at<cv::Vec3f>(row, x);
        for (int c = 0; c < 3; ++c) base[c] = static_cast<float>(std::clamp(p.base_color[c], 0.0, 1.0));
        m.metallic_roughness.at<cv::Vec3f>(row, x) =
            cv::Vec3f(1, static_cast<float>(std::clamp(p.roughness, 0.0, 1.0)), static_cast<float>(std::clamp(p.metallic, 0.0, 1.0)));
        if (p.normal.squaredNorm() == 0) continue;
        Eigen::Vector3d nrm = Eigen::Vector3d::Zero(), tan = Eigen::Vector3d::Zero();
        double w = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          nrm += b[static_cast<Eigen::Index>(k)] * mesh.normals[mesh.triangles[tri][k]];
          tan += b[static_cast<Eigen::Index>(k)] * tangents[tri][k].head<3>();
          w += b[static_cast<Eigen::Index>(k)] * tangents[tri][k].w();
        }
        if (nrm.norm() < 1e-12 || tan.norm() < 1e-12) continue;
        nrm.normalize();
        tan.normalize();
        const Eigen::Vector3d bit = nrm.cross(tan) * (w < 0 ? -1.0 : 1.0);
        // Coordinates in the (T, B, N) basis the viewer will use. The interpolated T is not
        // exactly orthogonal to N, so solve rather than project: T x + B y + N z is then
        // parallel to the refined normal for a viewer that does not re-orthogonalise, and
        // off by the small T.N for one that does.
        Eigen::Matrix3d frame;
        frame << tan, bit, nrm;
        Eigen::Vector3d local(p.normal.dot(tan), p.normal.dot(bit), p.normal.dot(nrm));
        if (std::abs(frame.determinant()) > 1e-6) local = frame.inverse() * p.normal;
        if (local.z() <= 0) local.z() = 1e-3;  // a viewer's normal map cannot point into the surface
        local.normalize();
        m.normal.at<cv::Vec3f>(row, x) = cv::Vec3f(static_cast<float>(local.x()), static_cast<float>(local.y()),
                                                   static_cast<float>(local.z()));
      }
  });
  return m;
}

}  // namespace fest::brdffit
