#include "brdffit/synthetic_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "core/error.hpp"

namespace fest::brdffit {

using reflectance::LafortuneBrdf;
using reflectance::LafortuneLobe;
using reflectance::Rgb;
using reflectance::TriangleMesh;

TriangleMesh icosphere(int level, double radius) {
  if (level < 0 || level > 9) throw usage_error("sphere subdivision level {} outside 0..9", level);
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (auto& p : v) p.normalize();
  std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      const auto idx = static_cast<std::uint32_t>(v.size() - 1);
      mid.emplace(key, idx);
      return idx;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    next.reserve(f.size() * 4);
    for (const auto& t : f) {
      const std::uint32_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    f.swap(next);
  }
  TriangleMesh m;
  m.normals = v;
  for (auto& p : v) p *= radius;
  m.vertices = std::move(v);
  m.triangles = std::move(f);
  return m;
}

LafortuneLobe mirror_lobe(const Rgb& rho_s, double exponent) {
  LafortuneLobe lobe;
  for (int c = 0; c < 3; ++c) {
    const double peak = rho_s[c] * (exponent + 2) / (2 * M_PI);
    const double coeff = std::pow(peak, 1.0 / exponent);
    lobe.cxy[c] = -coeff;
    lobe.cz[c] = coeff;
    lobe.n[c] = exponent;
  }
  return lobe;
}

std::vector<LafortuneBrdf> palette(int count) {
  auto one = [](Rgb rho_d, Rgb rho_s, double n) {
    LafortuneBrdf b;
    b.rho_d = rho_d;
    b.lobes = {mirror_lobe(rho_s, n)};
    return b;
  };
  const std::vector<LafortuneBrdf> base = {
      one(Rgb(0.55, 0.08, 0.06), Rgb(0.25, 0.25, 0.25), 60),    // red plastic
      one(Rgb(0.10, 0.20, 0.55), Rgb(0.03, 0.03, 0.03), 5),     // blue matte
      one(Rgb(0.08, 0.06, 0.02), Rgb(0.80, 0.60, 0.20), 120),   // gold metal
      one(Rgb(0.12, 0.45, 0.15), Rgb(0.12, 0.12, 0.12), 20),    // green satin
      one(Rgb(0.70, 0.68, 0.65), Rgb(0.05, 0.05, 0.05), 8),     // white clay
      reflectance::clay(),                                      // pbrt's measured clay
  };
  std::vector<LafortuneBrdf> out;
  for (int i = 0; i < count; ++i) out.push_back(base[static_cast<std::size_t>(i) % base.size()]);
  return out;
}

std::vector<std::uint16_t> material_patches(const TriangleMesh& mesh, int count, std::uint64_t seed) {
  if (count < 1 || count > 65535) throw usage_error("{} materials: 1..65535 expected", count);
  std::vector<std::uint16_t> id(mesh.triangles.size(), 0);
  if (mesh.vertices.empty()) return id;
  std::vector<Eigen::Vector3d> seeds = {mesh.vertices[seed % mesh.vertices.size()]};
  std::vector<double> dist(mesh.vertices.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(seeds.size()) < count) {
    std::size_t far = 0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      dist[i] = std::min(dist[i], (mesh.vertices[i] - seeds.back()).squaredNorm());
      if (dist[i] > dist[far]) far = i;
    }
    seeds.push_back(mesh.vertices[far]);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d c = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3;
    std::size_t best = 0;
    for (std::size_t s = 1; s < seeds.size(); ++s)
      if ((c - seeds[s]).squaredNorm() < (c - seeds[best]).squaredNorm()) best = s;
    id[t] = static_cast<std::uint16_t>(best);
  }
  return id;
}

void perturb_normals(TriangleMesh& mesh, double max_degrees, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (auto& n : mesh.normals) {
    const Eigen::Matrix3d frame = reflectance::local_frame(n);
    const double tilt = max_degrees * M_PI / 180 * unit(rng), phi = 2 * M_PI * unit(rng);
    const Eigen::Vector3d local(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi), std::cos(tilt));
    n = (frame * local).normalized();
  }
}

std::vector<TurntableImage> turntable_images(const TriangleMesh& mesh, const TurntableSetup& s) {
  if (s.views < 1 || s.lights < 1 || s.width < 8 || s.height < 8)
    throw usage_error("turntable: {} views, {} lights, {}x{} pixels", s.views, s.lights, s.width, s.height);
  if (!(s.distance > 1.05)) throw usage_error("camera distance {} radii must exceed 1.05", s.distance);
  Eigen::Vector3d c;
  double r = 0;
  reflectance::bounding_sphere(mesh, c, r);
  if (!(r > 0)) throw bad_input("the mesh has no extent");
  const double D = s.distance * r, e = s.elevation_deg * M_PI / 180;
  const Eigen::Vector3d eye0 = c + D * Eigen::Vector3d(0, -std::cos(e), std::sin(e));
  reflectance::PinholeCamera cam0;
  cam0.width = s.width;
  cam0.height = s.height;
  const double half = std::asin(1 / s.distance);
  cam0.fx = cam0.fy = s.fill * 0.5 * std::min(s.width, s.height) / std::tan(half);
  cam0.cx = 0.5 * (s.width - 1);
  cam0.cy = 0.5 * (s.height - 1);
  cam0.R = reflectance::look_at_rotation(eye0, c, Eigen::Vector3d::UnitZ());
  cam0.t = -cam0.R * eye0;
  // Lights fixed in the camera frame: light l sits on a circle of radius 0.6 D around the
  // camera, starting to the upper right (camera x right, y down).
  std::vector<Eigen::Vector3d> lights_cam;
  for (int l = 0; l < s.lights; ++l) {
    const double a = -M_PI / 4 + 2 * M_PI * l / s.lights;
    lights_cam.push_back(Eigen::Vector3d(0.6 * D * std::cos(a), 0.6 * D * std::sin(a), 0));
  }
  // A white Lambertian surface (rho_d = 1) facing a light at distance ~D reads I / (pi D^2).
  const double intensity = s.light_intensity > 0 ? s.light_intensity : M_PI * D * D;
  std::vector<TurntableImage> out;
  for (int a = 0; a < s.views; ++a) {
    const double theta_deg = 360.0 * a / s.views;
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(theta_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    reflectance::PinholeCamera cam = cam0;
    // X_cam = R0 (Rz (X - c) + c) + t0: the object turns about the axis through c.
    cam.R = cam0.R * Rz;
    cam.t = cam0.R * (c - Rz * c) + cam0.t;
    for (int l = 0; l < s.lights; ++l) {
      TurntableImage img;
      img.view.camera = cam;
      img.view.light.position = cam.R.transpose() * (lights_cam[static_cast<std::size_t>(l)] - cam.t);
      img.view.light.intensity = Rgb::Constant(intensity);
      img.angle_index = a;
      img.angle_deg = theta_deg;
      img.light = l;
      out.push_back(img);
    }
  }
  return out;
}

}  // namespace fest::brdffit
