#include "radiosity/model.hpp"

#include <algorithm>
#include <cmath>

namespace fest::radiosity {

double Polygon::area() const {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) s += p[k].cross(p[(k + 1) % n]);
  return 0.5 * s.norm();
}

Eigen::Vector3d Polygon::centroid() const {
  if (n == 3) return (p[0] + p[1] + p[2]) / 3.0;
  // Quad: area-weighted centroids of the two triangles (0,1,2) and (0,2,3).
  const double a1 = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  const double a2 = 0.5 * (p[2] - p[0]).cross(p[3] - p[0]).norm();
  const Eigen::Vector3d c1 = (p[0] + p[1] + p[2]) / 3.0, c2 = (p[0] + p[2] + p[3]) / 3.0;
  if (a1 + a2 <= 0) return (p[0] + p[1] + p[2] + p[3]) / 4.0;
  return (a1 * c1 + a2 * c2) / (a1 + a2);
}

Eigen::Vector3d Polygon::normal() const {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) s += p[k].cross(p[(k + 1) % n]);
  const double len = s.norm();
  return len > 0 ? Eigen::Vector3d(s / len) : Eigen::Vector3d::Zero();
}

double Polygon::longest_edge() const {
  double m = 0;
  for (int k = 0; k < n; ++k) m = std::max(m, (p[(k + 1) % n] - p[k]).norm());
  return m;
}

Eigen::Vector3d Polygon::sample(double s, double t) const {
  if (n == 4) return (1 - s) * (1 - t) * p[0] + s * (1 - t) * p[1] + s * t * p[2] + (1 - s) * t * p[3];
  const double r = std::sqrt(s);
  return (1 - r) * p[0] + r * (1 - t) * p[1] + r * t * p[2];
}

std::vector<int> Model::active_elements() const {
  std::vector<int> out;
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].active) out.push_back(static_cast<int>(e));
  return out;
}

void Model::reset_solution() {
  for (auto& pt : patches) {
    pt.B = pt.E;
    pt.U = pt.E;
    pt.S = Rgb::Zero();
  }
  for (auto& e : elements) {
    e.B = patches[e.patch].E;
    e.H = Rgb::Zero();
  }
}

void Model::update_patch_radiosity(int p) {
  Patch& pt = patches[p];
  Rgb sum = Rgb::Zero();
  double a = 0;
  for (int e : pt.elements) {
    sum += elements[e].area * elements[e].B;
    a += elements[e].area;
  }
  if (a > 0) pt.B = sum / a;
}

}  // namespace fest::radiosity
