#pragma once
// Scenes shared by the lmfsim unit tests, built in memory (no JSON).
#include <cmath>

#include "lmfsim/model.hpp"
#include "lmfsim/reduced.hpp"

namespace lmfsim_test {

using namespace fest::lmfsim;
constexpr double kPi = 3.14159265358979323846;

inline Body particle(const std::string& name, const Vec3& p, double m = 1) {
  Body b;
  b.name = name;
  b.kind = BodyKind::particle;
  b.mass = m;
  b.pos = p;
  return b;
}

inline Body box_body(const std::string& name, const Vec3& p, const Vec3& size, double m, const Quat& q = Quat::Identity()) {
  Body b;
  b.name = name;
  b.kind = BodyKind::rigid;
  b.mass = m;
  b.pos = p;
  b.quat = q;
  b.shape.kind = Shape::Kind::box;
  b.shape.dims = size;
  b.inertia = shape_inertia(b.shape, m);
  return b;
}

inline Constraint distance(const std::string& name, int a, int b, double L, const Vec3& pa = Vec3::Zero()) {
  Constraint c;
  c.name = name;
  c.type = ConstraintType::distance;
  c.a = a;
  c.b = b;
  c.pa = pa;
  c.length = L;
  return c;
}

inline Constraint hinge(const std::string& name, int a, const Vec3& pa, int b, const Vec3& pb, const Vec3& axis = Vec3::UnitY()) {
  Constraint c;
  c.name = name;
  c.type = ConstraintType::hinge;
  c.a = a;
  c.b = b;
  c.pa = pa;
  c.pb = pb;
  c.axis_a = axis;
  c.axis_b = axis;
  return c;
}

// Particle pendulums: N particles of mass m on massless rods of length l from the
// origin, angles th[i] from the downward vertical in the x-z plane.
inline Scene particle_chain(const std::vector<double>& th, double l = 1, double m = 1) {
  Scene s;
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < th.size(); ++i) {
    p += l * Vec3(std::sin(th[i]), 0, -std::cos(th[i]));
    s.bodies.push_back(particle("p" + std::to_string(i + 1), p, m));
    s.constraints.push_back(distance("r" + std::to_string(i + 1), static_cast<int>(i) - 1, static_cast<int>(i), l));
  }
  s.sim.dt = 1e-3;
  s.sim.every = 1;
  return s;
}

// Four-bar of uniform box links 1 kg/m, crank angle phi (rad), crank rate w, as gen fourbar.
inline Scene fourbar(double phi, double w, double g, FourBar& fb) {
  fb = FourBar();
  const FourBar::Pose p = fb.pose(phi);
  const double eps = 1e-6;
  const FourBar::Pose p1 = fb.pose(phi + eps), p0 = fb.pose(phi - eps);
  const double len[3] = {fb.a, fb.b, fb.c};
  const char* names[3] = {"crank", "coupler", "rocker"};
  Scene s;
  s.gravity = Vec3(0, 0, -g);
  for (int i = 0; i < 3; ++i) {
    Body b = box_body(names[i], Vec3(p.com[i].x(), 0, p.com[i].y()), Vec3(len[i], 0.02, 0.02), len[i],
                      Quat(Eigen::AngleAxisd(-p.angle[i], Vec3::UnitY())));
    const Eigen::Vector2d v = (p1.com[i] - p0.com[i]) / (2 * eps) * w;
    b.vel = Vec3(v.x(), 0, v.y());
    b.omega = Vec3(0, -std::remainder(p1.angle[i] - p0.angle[i], 2 * kPi) / (2 * eps) * w, 0);
    s.bodies.push_back(b);
    fb.m[i] = b.mass;
    fb.J[i] = b.inertia(1, 1);
  }
  fb.g = g;
  s.constraints.push_back(hinge("h0", kWorld, Vec3::Zero(), 0, Vec3(-fb.a / 2, 0, 0)));
  s.constraints.push_back(hinge("h1", 0, Vec3(fb.a / 2, 0, 0), 1, Vec3(-fb.b / 2, 0, 0)));
  s.constraints.push_back(hinge("h2", 1, Vec3(fb.b / 2, 0, 0), 2, Vec3(fb.c / 2, 0, 0)));
  s.constraints.push_back(hinge("h3", kWorld, Vec3(fb.d, 0, 0), 2, Vec3(-fb.c / 2, 0, 0)));
  s.sim.dt = 1e-3;
  s.sim.every = 1;
  return s;
}

}  // namespace lmfsim_test
