#pragma once
// The in-memory scene of lmfsim (docs/lmfsim.md): bodies, constraints, force elements,
// events and simulation settings. Pure data; parsing and writing live in tools/lmfsim.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lmfsim/spline.hpp"

namespace fest::lmfsim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

constexpr int kWorld = -1;  // body index of the implicit, fixed `world`

enum class BodyKind { particle, rigid };

// Geometry used for inertia ("auto") and for export. Meshes are kept as loaded
// (re-centred at the COM) so that export can draw them.
struct Shape {
  enum class Kind { none, box, sphere, cylinder, rod, mesh } kind = Kind::none;
  Vec3 dims = Vec3::Zero();  // box: full lengths; sphere: r; cylinder: r, length; rod: length
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

struct Body {
  std::string name;
  BodyKind kind = BodyKind::rigid;
  double mass = 1;
  Mat3 inertia = Mat3::Identity();  // body frame, about the COM (rigid only)
  bool fixed = false;
  Vec3 pos = Vec3::Zero();
  Quat quat = Quat::Identity();  // body -> world
  Vec3 vel = Vec3::Zero();
  Vec3 omega = Vec3::Zero();  // world frame
  Shape shape;
};

enum class ConstraintType {
  ball, hinge, axis_parallel, slider, weld, distance, point_on_plane, point_on_line,
  point_on_circle, path, motor, knife_edge
};

// A scalar that is either constant or a natural cubic spline of time.
struct Signal {
  double value = 0;
  Spline keys;  // used when !keys.empty()
  double at(double t) const { return keys.empty() ? value : keys.value(t); }
  double rate(double t) const { return keys.empty() ? 0.0 : keys.derivative(t); }
  double accel(double t) const { return keys.empty() ? 0.0 : keys.second_derivative(t); }
};

struct Signal3 {
  std::array<Signal, 3> c;
  Vec3 at(double t) const { return {c[0].at(t), c[1].at(t), c[2].at(t)}; }
  Vec3 rate(double t) const { return {c[0].rate(t), c[1].rate(t), c[2].rate(t)}; }
  Vec3 accel(double t) const { return {c[0].accel(t), c[1].accel(t), c[2].accel(t)}; }
};

struct Constraint {
  std::string name;
  ConstraintType type = ConstraintType::ball;
  int a = kWorld, b = kWorld;      // body indices (kWorld for the world)
  Vec3 pa = Vec3::Zero(), pb = Vec3::Zero();  // anchors in the body frames (world: world points)
  Vec3 axis_a = Vec3::UnitZ(), axis_b = Vec3::UnitZ();  // unit, body frames
  double length = 1;               // distance
  Vec3 origin = Vec3::Zero();      // point_on_*: o
  Vec3 direction = Vec3::UnitZ();  // plane normal, line direction, circle normal (unit)
  double radius = 1;               // point_on_circle
  Signal3 path;                    // path: pi(t)
  Signal omega;                    // motor: Omega(t)
  Quat rest = Quat::Identity();    // weld/slider: rest relative orientation q0 (q_a = q_b q0)
  bool active = true;
};

enum class ForceType { spring, drag, constant, pid };

struct ForceElement {
  std::string name;
  ForceType type = ForceType::spring;
  int a = kWorld, b = kWorld;  // spring ends; drag/constant/pid: a (drag: kWorld = every body)
  Vec3 pa = Vec3::Zero(), pb = Vec3::Zero();
  double k = 0, d = 0, rest = 0;        // spring
  double linear = 0, angular = 0;       // drag
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  bool body_frame = false;              // constant: force/torque given in the body frame
  Signal3 goal;                         // pid
  Vec3 kx = Vec3::Zero(), kv = Vec3::Zero(), ki = Vec3::Zero();
  bool active = true;
};

enum class EventAction { activate, deactivate, set, set_param };

struct Event {
  double t = 0;
  EventAction action = EventAction::activate;
  std::string target;  // "name" or "name.field"
  std::vector<double> value;
};

enum class Integrator { euler, symplectic, rk4, rk45 };
enum class Stabilization { none, baumgarte, force, project };
enum class SolverKind { baraff, dense };
enum class Formulation { lmf, penalty };

struct SimSettings {
  double t_end = 1;
  double dt = 1e-3;
  int every = 10;
  Integrator integrator = Integrator::rk4;
  Stabilization stab = Stabilization::baumgarte;
  double alpha = 10, beta = 10;
  SolverKind solver = SolverKind::baraff;
  Formulation formulation = Formulation::lmf;
  double kappa = 1, omega0 = 100, zeta = 1;
  double svd_tol = 1e-10;
  double max_violation = -1;  // < 0: 0.01 * length scale
  double rtol = 1e-8, atol = 1e-10;
};

struct Scene {
  Vec3 gravity{0, 0, -9.81};
  double length_scale = -1;  // < 0: from the initial configuration
  std::vector<Body> bodies;
  std::vector<Constraint> constraints;
  std::vector<ForceElement> forces;
  std::vector<Event> events;
  SimSettings sim;
};

// Rows of each constraint type (docs/lmfsim.md §2).
int constraint_rows(ConstraintType t);
// True for velocity-level (non-holonomic) rows: motor, knife_edge.
bool is_velocity_constraint(ConstraintType t);
const char* constraint_type_name(ConstraintType t);

// Body-frame inertia from a primitive shape and mass (docs/lmfsim.md "inertia: auto").
Mat3 shape_inertia(const Shape& shape, double mass);

// Mass, COM and inertia about the COM of a closed triangle mesh of unit density by
// the divergence theorem over signed tetrahedra (Mirtich 1996). volume <= 0 means the
// mesh is not closed or inside-out.
struct MassProperties {
  double volume = 0;
  Vec3 com = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();  // per unit density, about the COM
};
MassProperties mesh_mass_properties(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris);

// Checks the scene's invariants (indices, masses, inertia SPD, unit quaternions, axes,
// lengths) and completes derived fields (rest orientations). Throws bad_input.
void validate_scene(Scene& scene);

}  // namespace fest::lmfsim
