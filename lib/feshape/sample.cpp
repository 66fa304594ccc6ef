#include "feshape/sample.hpp"

#include <cmath>

#include "core/rng.hpp"

namespace fest::feshape {

std::vector<Eigen::Vector3d> sample_points(const Model& m, const SampleOptions& o) {
  Rng rng(o.seed);
  auto sphere_dir = [](double u, double v) {
    return Eigen::Vector3d(std::cos(u) * std::cos(v), std::cos(u) * std::sin(v), std::sin(u));
  };
  std::vector<Eigen::Vector3d> bump_centres;
  for (int k = 0; k < o.bumps; ++k) {
    const double u = std::asin(rng.uniform(-1, 1)), v = rng.uniform(-pi, pi);
    bump_centres.push_back(sphere_dir(u, v));
  }
  constexpr double width = 0.35;  // bump radius on the unit sphere (about 20 degrees)
  std::vector<Eigen::Vector3d> points;
  points.reserve(o.count);
  for (std::size_t i = 0; i < o.count; ++i) {
    const double u = std::asin(rng.uniform(-1, 1)), v = rng.uniform(-pi, pi);
    Eigen::Vector3d s = shape(m.qs, u, v);
    if (!bump_centres.empty()) {
      double h = 0;
      const Eigen::Vector3d w = sphere_dir(u, v);
      for (const auto& c : bump_centres) h += std::exp(-(w - c).squaredNorm() / (2 * width * width));
      const double len = s.norm();
      if (len > 0) s += o.bump_amplitude * m.qs[ia] * h * s / len;
    }
    Eigen::Vector3d x = m.center + m.rotation * s;
    if (o.noise > 0) x += o.noise * Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal());
    points.push_back(x);
  }
  return points;
}

}  // namespace fest::feshape
