// Scene invariants, constraint row counts and inertia of shapes and meshes.
#include <cmath>
#include <set>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "lmfsim/model.hpp"

namespace fest::lmfsim {

int constraint_rows(ConstraintType t) {
  switch (t) {
    case ConstraintType::ball: return 3;
    case ConstraintType::hinge: return 5;
    case ConstraintType::axis_parallel: return 2;
    case ConstraintType::slider: return 5;
    case ConstraintType::weld: return 6;
    case ConstraintType::distance: return 1;
    case ConstraintType::point_on_plane: return 1;
    case ConstraintType::point_on_line: return 2;
    case ConstraintType::point_on_circle: return 2;
    case ConstraintType::path: return 3;
    case ConstraintType::motor: return 1;
    case ConstraintType::knife_edge: return 1;
  }
  return 0;
}

bool is_velocity_constraint(ConstraintType t) {
  return t == ConstraintType::motor || t == ConstraintType::knife_edge;
}

const char* constraint_type_name(ConstraintType t) {
  switch (t) {
    case ConstraintType::ball: return "ball";
    case ConstraintType::hinge: return "hinge";
    case ConstraintType::axis_parallel: return "axis_parallel";
    case ConstraintType::slider: return "slider";
    case ConstraintType::weld: return "weld";
    case ConstraintType::distance: return "distance";
    case ConstraintType::point_on_plane: return "point_on_plane";
    case ConstraintType::point_on_line: return "point_on_line";
    case ConstraintType::point_on_circle: return "point_on_circle";
    case ConstraintType::path: return "path";
    case ConstraintType::motor: return "motor";
    case ConstraintType::knife_edge: return "knife_edge";
  }
  return "?";
}

Mat3 shape_inertia(const Shape& s, double m) {
  const Vec3& d = s.dims;
  switch (s.kind) {
    case Shape::Kind::box:
      return (m / 12 * Vec3(d.y() * d.y() + d.z() * d.z(), d.x() * d.x() + d.z() * d.z(),
                            d.x() * d.x() + d.y() * d.y())).asDiagonal();
    case Shape::Kind::sphere: return Mat3::Identity() * (0.4 * m * d.x() * d.x());
    case Shape::Kind::cylinder: {
      const double r = d.x(), l = d.y(), side = m * (3 * r * r + l * l) / 12;
      return Vec3(side, side, 0.5 * m * r * r).asDiagonal();
    }
    case Shape::Kind::rod: {  // cylinder of radius 0.01 L along local x
      const double l = d.x(), r = 0.01 * l, side = m * (3 * r * r + l * l) / 12;
      return Vec3(0.5 * m * r * r, side, side).asDiagonal();
    }
    default: return Mat3::Zero();
  }
}

MassProperties mesh_mass_properties(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris) {
  // Signed tetrahedra (origin, a, b, c): volume, first and second moments integrated
  // exactly (the covariance of a tetrahedron with one vertex at the origin).
  double vol = 0;
  Vec3 first = Vec3::Zero();
  Mat3 cov = Mat3::Zero();
  const Mat3 canonical = (Mat3() << 2, 1, 1, 1, 2, 1, 1, 1, 2).finished() / 120.0;
  for (const auto& t : tris) {
    Mat3 A;
    A.col(0) = v[static_cast<std::size_t>(t[0])];
    A.col(1) = v[static_cast<std::size_t>(t[1])];
    A.col(2) = v[static_cast<std::size_t>(t[2])];
    const double det = A.determinant();
    vol += det / 6;
    first += det / 24 * (A.col(0) + A.col(1) + A.col(2));
    cov += det * A * canonical * A.transpose();
  }
  MassProperties p;
  p.volume = vol;
  if (vol <= 0) return p;
  p.com = first / vol;
  const Mat3 c = cov - vol * p.com * p.com.transpose();  // shift to the COM
  p.inertia = Mat3::Identity() * c.trace() - c;
  return p;
}

void validate_scene(Scene& scene) {
  std::set<std::string> names;
  const int nb = static_cast<int>(scene.bodies.size());
  for (auto& b : scene.bodies) {
    if (b.name.empty() || b.name == "world") throw bad_input("body name '{}' is reserved or empty", b.name);
    if (!names.insert(b.name).second) throw bad_input("duplicate name '{}'", b.name);
    if (!(b.mass > 0) || !std::isfinite(b.mass)) throw bad_input("body '{}': mass {} must be positive", b.name, b.mass);
    const double qn = b.quat.norm();
    if (!std::isfinite(qn) || std::abs(qn - 1) > 1e-6)
      throw bad_input("body '{}': quaternion has norm {} (must be unit)", b.name, qn);
    b.quat.normalize();
    if (!b.pos.allFinite() || !b.vel.allFinite() || !b.omega.allFinite())
      throw bad_input("body '{}': non-finite initial state", b.name);
    if (b.kind == BodyKind::rigid) {
      const Mat3& I = b.inertia;
      if (!I.allFinite() || (I - I.transpose()).norm() > 1e-9 * (1 + I.norm()))
        throw bad_input("body '{}': inertia must be a symmetric 3x3 matrix", b.name);
      Eigen::SelfAdjointEigenSolver<Mat3> es(I);
      if (es.eigenvalues().minCoeff() <= 0)
        throw bad_input("body '{}': inertia is not positive definite (smallest eigenvalue {})", b.name,
                        es.eigenvalues().minCoeff());
    }
  }
  auto is_particle = [&](int i) { return i >= 0 && scene.bodies[static_cast<std::size_t>(i)].kind == BodyKind::particle; };
  auto is_ground = [&](int i) { return i == kWorld || scene.bodies[static_cast<std::size_t>(i)].fixed; };
  for (auto& c : scene.constraints) {
    if (c.name.empty()) throw bad_input("a constraint has no name");
    if (!names.insert(c.name).second) throw bad_input("duplicate name '{}'", c.name);
    if (c.a < kWorld || c.a >= nb || c.b < kWorld || c.b >= nb) throw bad_input("constraint '{}': body index out of range", c.name);
    if (c.a == c.b) throw bad_input("constraint '{}' joins a body to itself", c.name);
    if (is_ground(c.a) && is_ground(c.b)) throw bad_input("constraint '{}' joins two fixed bodies", c.name);
    const bool angular = c.type == ConstraintType::hinge || c.type == ConstraintType::axis_parallel ||
                         c.type == ConstraintType::slider || c.type == ConstraintType::weld ||
                         c.type == ConstraintType::motor || c.type == ConstraintType::knife_edge;
    if (angular && (is_particle(c.a) || is_particle(c.b)))
      throw bad_input("constraint '{}': a {} needs rigid bodies, not particles", c.name, constraint_type_name(c.type));
    if (is_particle(c.a) && c.pa.norm() != 0) throw bad_input("constraint '{}': anchor on particle must be [0,0,0]", c.name);
    if (is_particle(c.b) && c.pb.norm() != 0) throw bad_input("constraint '{}': anchor on particle must be [0,0,0]", c.name);
    for (Vec3* axis : {&c.axis_a, &c.axis_b, &c.direction}) {
      const double n = axis->norm();
      if (!(n > 1e-12) || !std::isfinite(n)) throw bad_input("constraint '{}': zero-length axis or direction", c.name);
      *axis /= n;
    }
    if (c.type == ConstraintType::distance && !(c.length > 0))
      throw bad_input("constraint '{}': length {} must be positive", c.name, c.length);
    if (c.type == ConstraintType::point_on_circle && !(c.radius > 0))
      throw bad_input("constraint '{}': radius {} must be positive", c.name, c.radius);
    if (c.type == ConstraintType::weld || c.type == ConstraintType::slider) {
      const Quat qa = c.a == kWorld ? Quat::Identity() : scene.bodies[static_cast<std::size_t>(c.a)].quat;
      const Quat qb = c.b == kWorld ? Quat::Identity() : scene.bodies[static_cast<std::size_t>(c.b)].quat;
      c.rest = (qb.conjugate() * qa).normalized();
    }
  }
  for (auto& f : scene.forces) {
    if (!f.name.empty() && !names.insert(f.name).second) throw bad_input("duplicate name '{}'", f.name);
    if (f.type == ForceType::spring && f.a == f.b) throw bad_input("spring joins a body to itself");
    if (f.type == ForceType::pid && f.a == kWorld) throw bad_input("pid needs a body");
  }
  const auto& sim = scene.sim;
  if (!(sim.dt > 0) || !std::isfinite(sim.dt)) throw usage_error("time step dt must be positive (got {})", sim.dt);
  if (!(sim.t_end >= 0) || !std::isfinite(sim.t_end)) throw usage_error("t_end must be >= 0 (got {})", sim.t_end);
  if (sim.every < 1) throw usage_error("frame interval every must be >= 1 (got {})", sim.every);
}

}  // namespace fest::lmfsim
