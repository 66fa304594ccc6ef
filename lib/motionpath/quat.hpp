#pragma once
// Unit quaternions for key-frame orientation (docs/quatpath.md "Orientation"): products,
// log/exp, slerp (Shoemake 1985) and squad (Shoemake 1987), with the sign choice that
// picks the short or the requested long way per segment (seed 004 §18).

namespace fest::motionpath {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double norm(Vec3 a);
double dot(Vec3 a, Vec3 b);
Vec3 cross(Vec3 a, Vec3 b);

struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
};
Quat operator*(const Quat& a, const Quat& b);  // Hamilton product
inline Quat operator-(const Quat& q) { return {-q.w, -q.x, -q.y, -q.z}; }
Quat conj(const Quat& q);
double dot(const Quat& a, const Quat& b);
double norm(const Quat& q);
Quat normalized(const Quat& q);
Quat from_axis_angle(Vec3 axis, double radians);
Vec3 rotate(const Quat& q, Vec3 v);  // q v q*

// log of a unit quaternion: (0, theta n) for q = (cos theta, sin theta n); exp its inverse.
Quat log_unit(const Quat& q);
Quat exp_pure(const Quat& p);

// Spherical linear interpolation along the great arc from a to b as given (no sign
// flip: callers choose -b for the other way). Unit in, unit out.
Quat slerp(const Quat& a, const Quat& b, double u);

// Shoemake's inner control point of key q with neighbours prev, next (already sign-
// adjusted): s = q exp(-(log(q* next) + log(q* prev)) / 4).
Quat squad_control(const Quat& prev, const Quat& q, const Quat& next);
// squad(q0, q1, s0, s1; u) = slerp(slerp(q0, q1, u), slerp(s0, s1, u), 2u(1 - u)).
Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, double u);

}  // namespace fest::motionpath
