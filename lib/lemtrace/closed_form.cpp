#include "lemtrace/closed_form.hpp"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/MatrixFunctions>

#include "lemtrace/flow_kernels.hpp"

namespace fest::lemtrace {

double psi(double lambda, double s) { return s * phi1(lambda * s); }

void eigen_flow(const CellRecord& r, const double z0[3], double s, double z[3]) { eigen_flow_inline(r, z0, s, z); }

CellPath::CellPath(const CellRecord& record, const Vec3& x0, double dir) : rec_(record), x0_(x0), dir_(dir) {
  switch (rec_.type) {
    case CellType::normal_real:
    case CellType::normal_complex:
      for (int i = 0; i < 3; ++i)
        z0_[i] = rec_.Sinv[3 * i] * x0[0] + rec_.Sinv[3 * i + 1] * x0[1] + rec_.Sinv[3 * i + 2] * x0[2];
      break;
    case CellType::parallel:
      s0_ = rec_.S[0] * x0[0] + rec_.S[1] * x0[1] + rec_.S[2] * x0[2] + rec_.c[0];
      break;
    case CellType::extraordinary:
      break;
  }
}

Vec3 CellPath::entry_velocity(const Vec3& field) const {
  if (rec_.type == CellType::parallel) return Vec3(rec_.lam[0], rec_.lam[1], rec_.lam[2]) * (dir_ * s0_);
  return dir_ * field;
}

Vec3 CellPath::entry_field() const {
  if (rec_.type == CellType::normal_real || rec_.type == CellType::normal_complex) {
    double dz[3];
    if (rec_.type == CellType::normal_real) {
      for (int i = 0; i < 3; ++i) dz[i] = rec_.lam[i] * z0_[i] + rec_.c[i];
    } else {
      const double a = rec_.lam[0], b = rec_.lam[1];
      dz[0] = a * z0_[0] + b * z0_[1] + rec_.c[0];
      dz[1] = -b * z0_[0] + a * z0_[1] + rec_.c[1];
      dz[2] = rec_.lam[2] * z0_[2] + rec_.c[2];
    }
    const double* S = rec_.S;
    return {S[0] * dz[0] + S[1] * dz[1] + S[2] * dz[2], S[3] * dz[0] + S[4] * dz[1] + S[5] * dz[2],
            S[6] * dz[0] + S[7] * dz[1] + S[8] * dz[2]};
  }
  if (rec_.type == CellType::parallel) return Vec3(rec_.lam[0], rec_.lam[1], rec_.lam[2]) * s0_;
  return dir_ * apply_A(x0_) + Vec3(rec_.c[0], rec_.c[1], rec_.c[2]);  // extraordinary: A x0 + b
}

double CellPath::rate() const {
  switch (rec_.type) {
    case CellType::normal_real:
      return std::max({std::abs(rec_.lam[0]), std::abs(rec_.lam[1]), std::abs(rec_.lam[2])});
    case CellType::normal_complex:
      // |alpha + i beta| (no over/underflow concern at the rates of a cell: no hypot call)
      return std::max(std::sqrt(rec_.lam[0] * rec_.lam[0] + rec_.lam[1] * rec_.lam[1]), std::abs(rec_.lam[2]));
    case CellType::parallel:
      return std::abs(rec_.c[1]);
    case CellType::extraordinary: {
      double m = 0;
      for (int i = 0; i < 9; ++i) m = std::max(m, std::abs(rec_.S[i]));
      return 3 * m;
    }
  }
  return 0;
}

Vec3 CellPath::apply_A(const Vec3& w) const {
  const double* S = rec_.S;
  const double* Si = rec_.Sinv;
  switch (rec_.type) {
    case CellType::normal_real:
    case CellType::normal_complex: {
      double z[3], y[3];
      for (int i = 0; i < 3; ++i) z[i] = Si[3 * i] * w[0] + Si[3 * i + 1] * w[1] + Si[3 * i + 2] * w[2];
      if (rec_.type == CellType::normal_real) {
        for (int i = 0; i < 3; ++i) y[i] = rec_.lam[i] * z[i];
      } else {
        const double a = rec_.lam[0], b = rec_.lam[1];
        y[0] = a * z[0] + b * z[1];
        y[1] = -b * z[0] + a * z[1];
        y[2] = rec_.lam[2] * z[2];
      }
      Vec3 r;
      for (int i = 0; i < 3; ++i) r[i] = dir_ * (S[3 * i] * y[0] + S[3 * i + 1] * y[1] + S[3 * i + 2] * y[2]);
      return r;
    }
    case CellType::parallel:  // A = d a^T
      return Vec3(rec_.lam[0], rec_.lam[1], rec_.lam[2]) * (dir_ * (S[0] * w[0] + S[1] * w[1] + S[2] * w[2]));
    case CellType::extraordinary: {
      Vec3 r;
      for (int i = 0; i < 3; ++i) r[i] = dir_ * (S[3 * i] * w[0] + S[3 * i + 1] * w[1] + S[3 * i + 2] * w[2]);
      return r;
    }
  }
  return Vec3::Zero();
}

void CellPath::apply_A2(const Vec3& w, Vec3& Aw, Vec3& AAw) const {
  if (rec_.type != CellType::normal_real && rec_.type != CellType::normal_complex) {
    Aw = apply_A(w);
    AAw = apply_A(Aw);
    return;
  }
  const double* S = rec_.S;
  const double* Si = rec_.Sinv;
  double z[3], y1[3], y2[3];
  for (int i = 0; i < 3; ++i) z[i] = Si[3 * i] * w[0] + Si[3 * i + 1] * w[1] + Si[3 * i + 2] * w[2];
  auto lambda = [&](const double* in, double* out) {
    if (rec_.type == CellType::normal_real) {
      for (int i = 0; i < 3; ++i) out[i] = rec_.lam[i] * in[i];
    } else {
      const double a = rec_.lam[0], b = rec_.lam[1];
      out[0] = a * in[0] + b * in[1];
      out[1] = -b * in[0] + a * in[1];
      out[2] = rec_.lam[2] * in[2];
    }
  };
  lambda(z, y1);
  lambda(y1, y2);
  for (int i = 0; i < 3; ++i) {
    Aw[i] = dir_ * (S[3 * i] * y1[0] + S[3 * i + 1] * y1[1] + S[3 * i + 2] * y1[2]);
    AAw[i] = dir_ * dir_ * (S[3 * i] * y2[0] + S[3 * i + 1] * y2[1] + S[3 * i + 2] * y2[2]);
  }
}

void CellPath::eval(double tau, Vec3& x, Vec3& v) const { eval_impl(tau, x, v, nullptr); }

void CellPath::eval(double tau, Vec3& x, Vec3& v, Vec3& a) const { eval_impl(tau, x, v, &a); }

void CellPath::eval_impl(double tau, Vec3& x, Vec3& v, Vec3* acc) const {
  const double s = dir_ * tau;
  switch (rec_.type) {
    case CellType::normal_real: {
      double z[3], dz[3];
      for (int i = 0; i < 3; ++i) {
        const double l = rec_.lam[i];
        double e, p;
        exp_and_psi(l, s, e, p);
        z[i] = e * z0_[i] + p * rec_.c[i];
        dz[i] = l * z[i] + rec_.c[i];
      }
      for (int r = 0; r < 3; ++r) {
        x[r] = rec_.S[3 * r] * z[0] + rec_.S[3 * r + 1] * z[1] + rec_.S[3 * r + 2] * z[2];
        v[r] = dir_ * (rec_.S[3 * r] * dz[0] + rec_.S[3 * r + 1] * dz[1] + rec_.S[3 * r + 2] * dz[2]);
      }
      if (acc) {  // a = dir A v = S Lambda dz (dir^2 = 1)
        const double d2[3] = {rec_.lam[0] * dz[0], rec_.lam[1] * dz[1], rec_.lam[2] * dz[2]};
        for (int r = 0; r < 3; ++r)
          (*acc)[r] = rec_.S[3 * r] * d2[0] + rec_.S[3 * r + 1] * d2[1] + rec_.S[3 * r + 2] * d2[2];
      }
      return;
    }
    case CellType::normal_complex: {
      const double a = rec_.lam[0], b = rec_.lam[1], l3 = rec_.lam[2];
      double z[3], dz[3];
      complex_pair_flow(a, b, s, z0_.data(), rec_.c, z);
      double e3, p3;
      exp_and_psi(l3, s, e3, p3);
      z[2] = e3 * z0_[2] + p3 * rec_.c[2];
      dz[0] = a * z[0] + b * z[1] + rec_.c[0];
      dz[1] = -b * z[0] + a * z[1] + rec_.c[1];
      dz[2] = l3 * z[2] + rec_.c[2];
      for (int r = 0; r < 3; ++r) {
        x[r] = rec_.S[3 * r] * z[0] + rec_.S[3 * r + 1] * z[1] + rec_.S[3 * r + 2] * z[2];
        v[r] = dir_ * (rec_.S[3 * r] * dz[0] + rec_.S[3 * r + 1] * dz[1] + rec_.S[3 * r + 2] * dz[2]);
      }
      if (acc) {  // a = dir A v = S Lambda dz (dir^2 = 1)
        const double d2[3] = {a * dz[0] + b * dz[1], -b * dz[0] + a * dz[1], l3 * dz[2]};
        for (int r = 0; r < 3; ++r)
          (*acc)[r] = rec_.S[3 * r] * d2[0] + rec_.S[3 * r + 1] * d2[1] + rec_.S[3 * r + 2] * d2[2];
      }
      return;
    }
    case CellType::parallel: {
      const Vec3 d(rec_.lam[0], rec_.lam[1], rec_.lam[2]);
      const double mu = rec_.c[1];
      x = x0_ + d * (s0_ * psi(mu, s));
      v = d * (dir_ * s0_ * std::exp(mu * s));
      if (acc) *acc = apply_A(v);
      return;
    }
    case CellType::extraordinary: {
      Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
      Mat3 A;
      for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = rec_.S[i];
      const Vec3 b(rec_.c[0], rec_.c[1], rec_.c[2]);
      M.topLeftCorner<3, 3>() = A * s;
      M.topRightCorner<3, 1>() = b * s;
      const Eigen::Matrix4d E = M.exp();
      x = E.topLeftCorner<3, 3>() * x0_ + E.topRightCorner<3, 1>();
      v = dir_ * (A * x + b);
      if (acc) *acc = apply_A(v);
      return;
    }
  }
}

}  // namespace fest::lemtrace
