#include "motionpath/quat.hpp"

#include <algorithm>
#include <cmath>

namespace fest::motionpath {

double norm(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

Quat operator*(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
Quat conj(const Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }
double dot(const Quat& a, const Quat& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }
double norm(const Quat& q) { return std::sqrt(dot(q, q)); }
Quat normalized(const Quat& q) {
  const double n = norm(q);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}
Quat from_axis_angle(Vec3 axis, double radians) {
  const double n = norm(axis);
  const double s = std::sin(radians / 2) / n;
  return {std::cos(radians / 2), axis.x * s, axis.y * s, axis.z * s};
}
Vec3 rotate(const Quat& q, Vec3 v) {
  const Quat r = q * Quat{0, v.x, v.y, v.z} * conj(q);
  return {r.x, r.y, r.z};
}

Quat log_unit(const Quat& q) {
  const double s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  if (s < 1e-300) return {0, 0, 0, 0};
  const double theta = std::atan2(s, q.w);
  const double k = theta / s;
  return {0, q.x * k, q.y * k, q.z * k};
}

Quat exp_pure(const Quat& p) {
  const double theta = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  if (theta < 1e-300) return {1, 0, 0, 0};
  const double k = std::sin(theta) / theta;
  return {std::cos(theta), p.x * k, p.y * k, p.z * k};
}

Quat slerp(const Quat& a, const Quat& b, double u) {
  // Shoemake 1985: a sin((1-u) W)/sin W + b sin(u W)/sin W, cos W = a.b. The angle comes
  // from atan2 of the chord lengths, accurate near W = 0 where acos(a.b) is not.
  const Quat d{b.w - a.w, b.x - a.x, b.y - a.y, b.z - a.z};
  const Quat s{b.w + a.w, b.x + a.x, b.y + a.y, b.z + a.z};
  const double omega = 2.0 * std::atan2(norm(d), norm(s));
  const double sin_omega = std::sin(omega);
  double ka, kb;
  if (sin_omega < 1e-12) {
    ka = 1.0 - u;  // a == b: the arc is a point
    kb = u;
  } else {
    ka = std::sin((1.0 - u) * omega) / sin_omega;
    kb = std::sin(u * omega) / sin_omega;
  }
  return normalized({ka * a.w + kb * b.w, ka * a.x + kb * b.x, ka * a.y + kb * b.y, ka * a.z + kb * b.z});
}

Quat squad_control(const Quat& prev, const Quat& q, const Quat& next) {
  const Quat qi = conj(q);
  const Quat l1 = log_unit(qi * next);
  const Quat l0 = log_unit(qi * prev);
  const Quat e{0, -(l1.x + l0.x) / 4, -(l1.y + l0.y) / 4, -(l1.z + l0.z) / 4};
  return normalized(q * exp_pure(e));
}

Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, double u) {
  return slerp(slerp(q0, q1, u), slerp(s0, s1, u), 2.0 * u * (1.0 - u));
}

}  // namespace fest::motionpath
