#include "facefit/evaluate.hpp"

#include <cmath>

#include "core/error.hpp"
#include "facefit/camera.hpp"
#include "facefit/fit.hpp"
#include "facefit/ridge.hpp"

namespace fest::facefit {

std::vector<double> vertex_errors(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int dims) {
  if (a.size() != b.size()) throw bad_input("shapes differ in size: {} and {} vertices", a.size() / dims, b.size() / dims);
  std::vector<double> e(static_cast<std::size_t>(a.size() / dims));
  for (std::size_t j = 0; j < e.size(); ++j)
    e[j] = (a.segment(static_cast<Eigen::Index>(j) * dims, dims) - b.segment(static_cast<Eigen::Index>(j) * dims, dims)).norm();
  return e;
}

double mean_error(const std::vector<double>& errors, const std::vector<std::uint32_t>& mask) {
  double sum = 0;
  if (mask.empty()) {
    for (double e : errors) sum += e;
    return errors.empty() ? 0 : sum / static_cast<double>(errors.size());
  }
  for (auto j : mask) {
    if (j >= errors.size()) throw bad_input("mask vertex {} out of range ({} vertices)", j, errors.size());
    sum += errors[j];
  }
  return sum / static_cast<double>(mask.size());
}

std::vector<SweepRow> sweep(const Model& model, const std::vector<Eigen::VectorXd>& faces,
                            const std::vector<std::uint32_t>& vertices, const std::vector<double>& etas,
                            const std::vector<SweepSetting>& settings, const std::vector<std::uint32_t>& mask,
                            std::uint64_t seed) {
  std::vector<SweepRow> rows;
  Rng rng(seed);
  const Eigen::Vector2d center(150, 150);
  const CameraMatrix truth = orthographic_camera(1.0, center);
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const Eigen::VectorXd& face = faces[fi];
    if (static_cast<std::size_t>(face.size()) != model.n())
      throw bad_input("face {} has {} vertices, the model {}", fi, face.size() / model.dims, model.points);
    for (const auto& setting : settings) {
      const Model sub = truncated(model, setting.components);
      Landmarks lm;
      lm.vertex = vertices;
      lm.uv.resize(2, static_cast<Eigen::Index>(vertices.size()));
      for (std::size_t a = 0; a < vertices.size(); ++a) {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int e = 0; e < model.dims; ++e) x(e) = face(static_cast<Eigen::Index>(vertices[a]) * model.dims + e);
        Eigen::Vector2d uv = truth.leftCols<3>() * x + truth.col(3);
        if (setting.sigma_noise > 0) {
          uv.x() += setting.sigma_noise * rng.normal();
          uv.y() += setting.sigma_noise * rng.normal();
        }
        lm.uv.col(static_cast<Eigen::Index>(a)) = uv;
      }
      check_landmarks(sub, lm);
      Eigen::MatrixXd Q;
      Eigen::VectorXd r;
      build_measurement(sub, lm, orthographic_camera(1.0, center, setting.yaw_deg), Eigen::VectorXd(), Q, r);
      const RidgeSolver solver(Q, r);
      for (double eta : etas) {
        const Eigen::VectorXd c = solver.coefficients(eta);
        SweepRow row;
        row.face = fi;
        row.setting = setting;
        row.f = vertices.size();
        row.eta = eta;
        row.E_r = (Q * c - r).norm();
        row.E_r_rms = row.E_r / std::sqrt(static_cast<double>(row.f));
        row.norm_c = c.norm();
        row.E_full = mean_error(vertex_errors(reconstruct(sub, c), face, model.dims), mask);
        rows.push_back(row);
      }
    }
  }
  return rows;
}

}  // namespace fest::facefit
