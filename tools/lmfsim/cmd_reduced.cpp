// lmfsim reduced: reduced-coordinate references for planar chains and the four-bar
// (docs/lmfsim.md §5), written in the layout of `run` so that `diff` can compare the two.
#include <cmath>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "lmfsim/reduced.hpp"
#include "trajectory_csv.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

namespace {

Quat rot_y(double a) { return Quat(Eigen::AngleAxisd(a, Vec3::UnitY())); }

void require_planar(const Scene& sc) {
  if (sc.gravity.x() != 0 || sc.gravity.y() != 0 || sc.gravity.z() > 0)
    throw fest::usage_error("reduced: gravity must point along -z for a planar reference");
  for (const Body& b : sc.bodies) {
    if (b.fixed) throw fest::usage_error("reduced: fixed bodies are not supported");
    if (std::abs(b.pos.y()) > 1e-12 || std::abs(b.vel.y()) > 1e-12 || std::abs(b.omega.x()) > 1e-12 ||
        std::abs(b.omega.z()) > 1e-12)
      throw fest::usage_error("reduced: body '{}' does not move in the x-z plane", b.name);
  }
  for (const ForceElement& f : sc.forces)
    throw fest::usage_error("reduced: force elements are not supported (found {})", f.name.empty() ? "one" : f.name);
  if (!sc.events.empty()) throw fest::usage_error("reduced: events are not supported");
}

struct Framing {
  double dt;
  long steps, every;
};

Framing framing(const Scene& sc, const SimOverrides& over) {
  const double period = sc.sim.dt * sc.sim.every;
  Framing f;
  f.dt = over.dt ? *over.dt : sc.sim.dt;
  const double t_end = over.t_end ? *over.t_end : sc.sim.t_end;
  if (!(f.dt > 0)) throw fest::usage_error("--dt must be positive");
  f.every = std::max(1L, std::lround(period / f.dt));
  if (std::abs(f.every * f.dt - period) > 1e-9 * period)
    throw fest::usage_error("reduced: --dt {} does not divide the scene's frame period {}", f.dt, period);
  f.steps = step_count(t_end, f.dt, over.dt || over.t_end);
  return f;
}

int reduced_chain(const Scene& sc, const SimOverrides& over) {
  require_planar(sc);
  // Walk the chain from its ground joint.
  const int nb = static_cast<int>(sc.bodies.size());
  std::vector<int> order, joint_in;
  std::vector<bool> used(sc.constraints.size(), false);
  int current = kWorld;
  Vec3 pivot = Vec3::Zero();
  for (int step = 0; step < nb; ++step) {
    int found = -1;
    for (std::size_t j = 0; j < sc.constraints.size(); ++j) {
      const Constraint& c = sc.constraints[j];
      if (used[j] || !c.active) continue;
      if (c.a == current || c.b == current) {
        if (found >= 0) throw fest::usage_error("reduced --chain: the scene is branched or has loops");
        found = static_cast<int>(j);
      }
    }
    if (found < 0) break;
    used[static_cast<std::size_t>(found)] = true;
    const Constraint& c = sc.constraints[static_cast<std::size_t>(found)];
    if (c.type != ConstraintType::hinge && c.type != ConstraintType::ball && c.type != ConstraintType::distance)
      throw fest::usage_error("reduced --chain: joint '{}' is a {}, not a hinge, ball or distance", c.name,
                              constraint_type_name(c.type));
    if (c.type == ConstraintType::hinge && (std::abs(std::abs(c.axis_a.y()) - 1) > 1e-12 || std::abs(std::abs(c.axis_b.y()) - 1) > 1e-12))
      throw fest::usage_error("reduced --chain: hinge '{}' is not about the y axis", c.name);
    const bool forward = c.a == current;
    if (current == kWorld) pivot = forward ? c.pa : c.pb;
    current = forward ? c.b : c.a;
    order.push_back(current);
    joint_in.push_back(found);
  }
  if (static_cast<int>(order.size()) != nb) throw fest::usage_error("reduced --chain: the bodies do not form one chain from the world");
  for (std::size_t j = 0; j < sc.constraints.size(); ++j)
    if (!used[j] && sc.constraints[j].active) throw fest::usage_error("reduced --chain: the scene has loops or extra constraints");
  ReducedChain ch;
  ch.g = -sc.gravity.z();
  Eigen::VectorXd th(nb), thd(nb);
  std::vector<Quat> q0(static_cast<std::size_t>(nb));
  Vec3 prev_point = pivot, prev_vel = Vec3::Zero();
  for (int i = 0; i < nb; ++i) {
    const Body& b = sc.bodies[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])];
    const Constraint& cin = sc.constraints[static_cast<std::size_t>(joint_in[static_cast<std::size_t>(i)])];
    ChainLink link;
    link.mass = b.mass;
    if (b.kind == BodyKind::particle) {
      if (cin.type != ConstraintType::distance) throw fest::usage_error("reduced --chain: particles need distance joints");
      const Vec3 d = b.pos - prev_point;
      link.length = cin.length;
      link.com = 1;
      th[i] = std::atan2(d.x(), -d.z());
      const Vec3 vr = b.vel - prev_vel;
      thd[i] = (vr.x() * std::cos(th[i]) + vr.z() * std::sin(th[i])) / link.length;
      prev_point = b.pos;
      prev_vel = b.vel;
    } else {
      const Vec3 r_in = cin.a == order[static_cast<std::size_t>(i)] ? cin.pa : cin.pb;
      const Mat3 R = b.quat.toRotationMatrix();
      Vec3 r_out = Vec3::Zero();
      bool has_child = i + 1 < nb;
      if (has_child) {
        const Constraint& cout = sc.constraints[static_cast<std::size_t>(joint_in[static_cast<std::size_t>(i) + 1])];
        r_out = cout.a == order[static_cast<std::size_t>(i)] ? cout.pa : cout.pb;
      }
      const Vec3 axis = has_child ? Vec3(R * (r_out - r_in)) : Vec3(-R * r_in);
      link.length = axis.norm();
      link.com = has_child ? r_in.norm() / link.length : 1.0;
      if (has_child && (r_in.normalized() + (r_out - r_in).normalized()).norm() > 1e-9)
        throw fest::usage_error("reduced --chain: link '{}' has its COM off the joint line", b.name);
      link.inertia = b.inertia(1, 1);
      th[i] = std::atan2(axis.x(), -axis.z());
      thd[i] = -b.omega.y();
      q0[static_cast<std::size_t>(i)] = b.quat;
    }
    ch.links.push_back(link);
  }
  const Eigen::VectorXd th0 = th;
  const Framing fr = framing(sc, over);
  std::string out = trajectory_header();
  auto frame = [&](long k) {
    const double t = static_cast<double>(k) * fr.dt;
    for (int i = 0; i < nb; ++i) {
      const Body& b = sc.bodies[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])];
      const Eigen::Vector2d p = ch.com_position(th, i), v = ch.com_velocity(th, thd, i);
      TrajectoryRow r;
      r.frame = k / fr.every;
      r.t = t;
      r.body = b.name;
      r.p = pivot + Vec3(p.x(), 0, p.y());
      r.v = Vec3(v.x(), 0, v.y());
      if (b.kind == BodyKind::rigid) {
        r.q = rot_y(th0[i] - th[i]) * q0[static_cast<std::size_t>(i)];
        r.w = Vec3(0, -thd[i], 0);
      } else {
        r.q = Quat::Identity();
        r.w = Vec3::Zero();
      }
      append_row(out, r);
    }
  };
  frame(0);
  for (long k = 1; k <= fr.steps; ++k) {
    ch.step_rk4(th, thd, fr.dt);
    if (!th.allFinite() || !thd.allFinite()) throw fest::runtime_failure("reduced: state became non-finite (t={:.6g})", k * fr.dt);
    if (k % fr.every == 0) frame(k);
  }
  fest::write_output("-", out);
  return 0;
}

int reduced_fourbar(const Scene& sc, const SimOverrides& over) {
  require_planar(sc);
  auto body = [&](const char* name) {
    for (std::size_t i = 0; i < sc.bodies.size(); ++i)
      if (sc.bodies[i].name == name) return static_cast<int>(i);
    throw fest::usage_error("reduced --fourbar: the scene has no body '{}' (use the layout of `lmfsim gen fourbar`)", name);
  };
  auto joint = [&](const char* name) -> const Constraint& {
    for (const Constraint& c : sc.constraints)
      if (c.name == name && c.type == ConstraintType::hinge) return c;
    throw fest::usage_error("reduced --fourbar: the scene has no hinge '{}' (use the layout of `lmfsim gen fourbar`)", name);
  };
  const int ids[3] = {body("crank"), body("coupler"), body("rocker")};
  if (sc.bodies.size() != 3 || sc.constraints.size() != 4) throw fest::usage_error("reduced --fourbar: expected 3 bodies and 4 hinges");
  FourBar fb;
  fb.a = 2 * joint("h0").pb.norm();
  fb.b = 2 * joint("h1").pb.norm();
  fb.c = 2 * joint("h3").pb.norm();
  fb.d = joint("h3").pa.norm();
  fb.g = -sc.gravity.z();
  for (int i = 0; i < 3; ++i) {
    const Body& b = sc.bodies[static_cast<std::size_t>(ids[i])];
    fb.m[i] = b.mass;
    fb.J[i] = b.inertia(1, 1);
  }
  const Body& crank = sc.bodies[static_cast<std::size_t>(ids[0])];
  const Vec3 dir = crank.quat * Vec3::UnitX();
  double phi = std::atan2(dir.z(), dir.x()), phid = -crank.omega.y();
  {
    const Body& coupler = sc.bodies[static_cast<std::size_t>(ids[1])];
    const Vec3 A3 = crank.pos + crank.quat * Vec3(fb.a / 2, 0, 0), B3 = coupler.pos + coupler.quat * Vec3(fb.b / 2, 0, 0);
    fb.branch = FourBar::branch_of({A3.x(), A3.z()}, {B3.x(), B3.z()}, {fb.d, 0});
  }
  const FourBar::Pose pose0 = fb.pose(phi);
  std::vector<Quat> q0;
  for (int i = 0; i < 3; ++i) q0.push_back(sc.bodies[static_cast<std::size_t>(ids[i])].quat);
  const Framing fr = framing(sc, over);
  std::string out = trajectory_header();
  auto frame = [&](long k) {
    const double eps = 1e-6;
    const FourBar::Pose p = fb.pose(phi), p1 = fb.pose(phi + eps), pm = fb.pose(phi - eps);
    for (int i = 0; i < 3; ++i) {
      TrajectoryRow r;
      r.frame = k / fr.every;
      r.t = static_cast<double>(k) * fr.dt;
      r.body = sc.bodies[static_cast<std::size_t>(ids[i])].name;
      r.p = Vec3(p.com[i].x(), 0, p.com[i].y());
      const Eigen::Vector2d v = (p1.com[i] - pm.com[i]) / (2 * eps) * phid;
      r.v = Vec3(v.x(), 0, v.y());
      const double rate = std::remainder(p1.angle[i] - pm.angle[i], 2 * 3.14159265358979323846) / (2 * eps) * phid;
      r.q = rot_y(-(p.angle[i] - pose0.angle[i])) * q0[static_cast<std::size_t>(i)];
      r.w = Vec3(0, -rate, 0);
      append_row(out, r);
    }
  };
  frame(0);
  for (long k = 1; k <= fr.steps; ++k) {
    fb.step_rk4(phi, phid, fr.dt);
    if (k % fr.every == 0) frame(k);
  }
  fest::write_output("-", out);
  return 0;
}

}  // namespace

int cmd_reduced(const ReducedOptions& opt) {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  if (opt.chain == opt.fourbar) throw fest::usage_error("reduced: give exactly one of --chain and --fourbar");
  const Scene sc = load_scene(scene_bytes);
  for (const Constraint& c : sc.constraints)
    if (is_velocity_constraint(c.type))
      throw fest::usage_error("reduced: velocity constraint '{}' ({}) has no reduced-coordinate form", c.name,
                              constraint_type_name(c.type));
  return opt.chain ? reduced_chain(sc, opt.sim) : reduced_fourbar(sc, opt.sim);
}

}  // namespace fest::lmfsim_tool
