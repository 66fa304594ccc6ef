// lmfsim gen: the scenes of the golden and analytic tests (docs/lmfsim.md §4 `gen`).
#include <cmath>

#include <fmt/format.h>

#include "core/resources.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/reduced.hpp"

namespace fest::lmfsim_tool {

using nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

json v3(double x, double y, double z) { return json::array({x, y, z}); }

// Quaternion of a rotation about +y by `a` radians (x -> (cos a, 0, -sin a)).
json quat_y(double a) { return json::array({std::cos(a / 2), 0.0, std::sin(a / 2), 0.0}); }

const char* joint_name(JointType j) {
  switch (j) {
    case JointType::ball: return "ball";
    case JointType::hinge: return "hinge";
    case JointType::distance: return "distance";
  }
  return "?";
}

json sim_block() {
  return {{"t_end", 1.0}, {"dt", 1e-3}, {"every", 10}, {"integrator", "rk4"},
          {"stab", {{"mode", "baumgarte"}, {"alpha", 10.0}, {"beta", 10.0}}}, {"solver", "baraff"}};
}

json gen_chain(const GenOptions& o) {
  if (o.n < 1) throw fest::usage_error("--n must be >= 1");
  const bool particle = o.type == LinkType::particle;
  const JointType joint =
      o.joint ? *o.joint : (particle ? JointType::distance : (o.planar ? JointType::hinge : JointType::ball));
  if (particle && joint != JointType::distance) throw fest::usage_error("a particle chain needs --joint distance");
  if (!particle && joint == JointType::distance) throw fest::usage_error("--joint distance needs --type particle");
  if (!(o.mass > 0) || !(o.length > 0)) throw fest::usage_error("--mass and --length must be positive");
  const double L = o.length / o.n, m = o.mass / o.n, th = o.angle * kPi / 180;
  const double dx = std::sin(th), dz = -std::cos(th);  // link direction from the downward vertical
  json bodies = json::array(), cons = json::array();
  for (int i = 0; i < o.n; ++i) {
    const std::string name = "l" + std::to_string(i + 1);
    json b = {{"name", name}, {"type", particle ? "particle" : "rigid"}, {"mass", m}};
    const double along = particle ? (i + 1) * L : (i + 0.5) * L;
    b["pos"] = v3(along * dx, 0, along * dz);
    if (!particle) {
      if (o.type == LinkType::box) b["shape"] = {{"box", v3(L, 0.02, 0.02)}};
      else b["shape"] = {{"rod", L}};
      b["inertia"] = "auto";
      b["quat"] = quat_y(kPi / 2 - th);
    }
    bodies.push_back(b);
    const std::string prev = i == 0 ? "world" : "l" + std::to_string(i);
    json c = {{"name", "j" + std::to_string(i)}, {"type", joint_name(joint)}, {"a", prev}, {"b", name}};
    if (particle) {
      c["length"] = L;
    } else {
      c["pa"] = i == 0 ? v3(0, 0, 0) : v3(L / 2, 0, 0);
      c["pb"] = v3(-L / 2, 0, 0);
      if (joint == JointType::hinge) {
        c["axis_a"] = v3(0, 1, 0);
        c["axis_b"] = v3(0, 1, 0);
      }
    }
    cons.push_back(c);
  }
  json sim = sim_block();
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons}, {"sim", sim}};
}

json gen_fourbar(const GenOptions& o) {
  fest::lmfsim::FourBar fb;
  fb.a = o.abcd[0], fb.b = o.abcd[1], fb.c = o.abcd[2], fb.d = o.abcd[3];
  fb.branch = 1;
  const double phi = o.angle * kPi / 180;
  fest::lmfsim::FourBar::Pose p;
  try {
    p = fb.pose(phi);
  } catch (const fest::Error&) {
    throw fest::usage_error("the four-bar {},{},{},{} cannot close at crank angle {} deg", fb.a, fb.b, fb.c, fb.d,
                            o.angle);
  }
  // Velocities for the crank rate omega0 by a central difference of the closed loop.
  const double eps = 1e-6;
  const auto p1 = fb.pose(phi + eps), p0 = fb.pose(phi - eps);
  const char* names[3] = {"crank", "coupler", "rocker"};
  const double len[3] = {fb.a, fb.b, fb.c};
  json bodies = json::array();
  for (int i = 0; i < 3; ++i) {
    const double m = len[i] * 1.0;  // uniform rods of 1 kg/m
    const Eigen::Vector2d vc = (p1.com[i] - p0.com[i]) / (2 * eps) * o.omega0;
    const double rate = std::remainder(p1.angle[i] - p0.angle[i], 2 * kPi) / (2 * eps) * o.omega0;
    // Link angle gamma (from +x toward +z) is a rotation about y by -gamma.
    bodies.push_back({{"name", names[i]}, {"type", "rigid"}, {"mass", m},
                      {"shape", {{"box", v3(len[i], 0.02, 0.02)}}}, {"inertia", "auto"},
                      {"pos", v3(p.com[i].x(), 0, p.com[i].y())}, {"quat", quat_y(-p.angle[i])},
                      {"vel", v3(vc.x(), 0, vc.y())}, {"omega", v3(0, -rate, 0)}});
  }
  auto hinge = [&](const char* name, const char* a, json pa, const char* b, json pb) {
    return json{{"name", name}, {"type", "hinge"}, {"a", a}, {"pa", pa}, {"b", b}, {"pb", pb},
                {"axis_a", v3(0, 1, 0)}, {"axis_b", v3(0, 1, 0)}};
  };
  json cons = json::array({hinge("h0", "world", v3(0, 0, 0), "crank", v3(-fb.a / 2, 0, 0)),
                           hinge("h1", "crank", v3(fb.a / 2, 0, 0), "coupler", v3(-fb.b / 2, 0, 0)),
                           hinge("h2", "coupler", v3(fb.b / 2, 0, 0), "rocker", v3(fb.c / 2, 0, 0)),
                           hinge("h3", "world", v3(fb.d, 0, 0), "rocker", v3(-fb.c / 2, 0, 0))});
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons}, {"sim", sim_block()}};
}

// Baumgarte activation: a particle 1.1 m from a pivot, moving at 0.3 m/s perpendicular
// to the (inactive) rod of length 1 m, which an event switches on at t = 0.5 s.
json gen_activation(const GenOptions& o) {
  json bodies = json::array({{{"name", "bob"}, {"type", "particle"}, {"mass", 1.0}, {"pos", v3(1.1, 0, 0)}, {"vel", v3(0, 0.3, 0)}}});
  json cons = json::array({{{"name", "rod"}, {"type", "distance"}, {"a", "world"}, {"b", "bob"}, {"length", 1.0}, {"active", false}}});
  json events = json::array({{{"t", 0.5}, {"action", "activate"}, {"target", "rod"}}});
  json sim = sim_block();
  sim["t_end"] = 3.0;
  sim["stab"] = {{"mode", "baumgarte"}, {"alpha", 5.0}, {"beta", 5.0}};
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons},
          {"events", events}, {"sim", sim}};
}

// Knife edge (docs/lmfsim.md §2, §7): a box held on z = 0 (point_on_plane at the COM, body z parallel
// to world z) with a blade along body x through the COM; speed 1 m/s, yaw rate --omega0:
// the COM runs on a circle of radius 1/omega0.
json gen_sleigh(const GenOptions& o) {
  json bodies = json::array({{{"name", "sleigh"}, {"type", "rigid"}, {"mass", o.mass},
                              {"shape", {{"box", v3(0.6, 0.3, 0.1)}}}, {"inertia", "auto"},
                              {"pos", v3(0, 0, 0)}, {"vel", v3(1, 0, 0)}, {"omega", v3(0, 0, o.omega0)}}});
  json cons = json::array({{{"name", "plane"}, {"type", "point_on_plane"}, {"a", "sleigh"},
                            {"plane", {{"o", v3(0, 0, 0)}, {"n", v3(0, 0, 1)}}}},
                           {{"name", "upright"}, {"type", "axis_parallel"}, {"a", "sleigh"}, {"b", "world"},
                            {"axis_a", v3(0, 0, 1)}, {"axis_b", v3(0, 0, 1)}},
                           {{"name", "blade"}, {"type", "knife_edge"}, {"a", "sleigh"}, {"pa", v3(0, 0, 0)},
                            {"axis_a", v3(0, 1, 0)}}});
  json sim = sim_block();
  sim["t_end"] = 10.0;
  return {{"gravity", v3(0, 0, 0)}, {"bodies", bodies}, {"constraints", cons}, {"sim", sim}};
}

// A bead (particle) on a vertical circle of radius --length through the origin's plane.
json gen_bead(const GenOptions& o) {
  const double th = o.angle * kPi / 180, r = o.length;
  json bodies = json::array({{{"name", "bead"}, {"type", "particle"}, {"mass", o.mass},
                              {"pos", v3(r * std::sin(th), 0, -r * std::cos(th))}}});
  json cons = json::array({{{"name", "wire"}, {"type", "point_on_circle"}, {"a", "bead"},
                            {"circle", {{"o", v3(0, 0, 0)}, {"n", v3(0, 1, 0)}, {"r", r}}}}});
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons}, {"sim", sim_block()}};
}

// An arm on a hinge whose motor (2 rad/s) is switched on at t = 0.5 s.
json gen_motorarm(const GenOptions& o) {
  const double L = o.length;
  json bodies = json::array({{{"name", "arm"}, {"type", "rigid"}, {"mass", o.mass},
                              {"shape", {{"box", v3(L, 0.05, 0.05)}}}, {"inertia", "auto"}, {"pos", v3(L / 2, 0, 0)}}});
  json cons = json::array({{{"name", "pivot"}, {"type", "hinge"}, {"a", "world"}, {"b", "arm"}, {"pb", v3(-L / 2, 0, 0)},
                            {"axis_a", v3(0, 1, 0)}, {"axis_b", v3(0, 1, 0)}},
                           {{"name", "motor"}, {"type", "motor"}, {"a", "world"}, {"b", "arm"}, {"axis_a", v3(0, 1, 0)},
                            {"omega", o.omega0 != 0 ? o.omega0 : 2.0}, {"active", false}}});
  json events = json::array({{{"t", 0.5}, {"action", "activate"}, {"target", "motor"}}});
  json sim = sim_block();
  sim["t_end"] = 2.0;
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons},
          {"events", events}, {"sim", sim}};
}

// A closed ring of N box links joined by hinges about y, hanging from a hinge to the
// world at its top: one loop, closed through auxiliary rows.
json gen_ring(const GenOptions& o) {
  const int n = o.n < 3 ? 8 : o.n;
  const double L = o.length / n, m = o.mass / n, R = L / (2 * std::sin(kPi / n));
  json bodies = json::array(), cons = json::array();
  // Vertices of a regular polygon in the x-z plane, vertex 0 at the pivot (origin), the
  // whole ring turned 30 degrees about the pivot so that it swings.
  const double tilt = kPi / 6;
  auto vertex = [&](int k) {
    const double a = 2 * kPi * k / n;
    const Eigen::Vector2d p(R * std::sin(a), R * std::cos(a) - R);
    return Eigen::Vector2d(p.x() * std::cos(tilt) - p.y() * std::sin(tilt), p.x() * std::sin(tilt) + p.y() * std::cos(tilt));
  };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = vertex(i), b = vertex((i + 1) % n), c = 0.5 * (a + b);
    const double gamma = std::atan2(b.y() - a.y(), b.x() - a.x());
    bodies.push_back({{"name", "k" + std::to_string(i)}, {"type", "rigid"}, {"mass", m},
                      {"shape", {{"box", v3(L, 0.02, 0.02)}}}, {"inertia", "auto"},
                      {"pos", v3(c.x(), 0, c.y())}, {"quat", quat_y(-gamma)}});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    cons.push_back({{"name", "h" + std::to_string(i)}, {"type", "hinge"}, {"a", "k" + std::to_string(i)},
                    {"pa", v3(L / 2, 0, 0)}, {"b", "k" + std::to_string(j)}, {"pb", v3(-L / 2, 0, 0)},
                    {"axis_a", v3(0, 1, 0)}, {"axis_b", v3(0, 1, 0)}});
  }
  cons.push_back({{"name", "top"}, {"type", "hinge"}, {"a", "world"}, {"pa", v3(0, 0, 0)}, {"b", "k0"},
                  {"pb", v3(-L / 2, 0, 0)}, {"axis_a", v3(0, 1, 0)}, {"axis_b", v3(0, 1, 0)}});
  return {{"gravity", v3(0, 0, o.gravity ? -9.81 : 0.0)}, {"bodies", bodies}, {"constraints", cons}, {"sim", sim_block()}};
}

}  // namespace

int cmd_gen(const GenOptions& o) {
  if (o.kind == GenScene::chain || o.kind == GenScene::ring)
    fest::check_fits_in_memory(static_cast<double>(o.n) * kGenBytesPerLink, fmt::format("a scene of --n {} links", o.n));
  json doc;
  switch (o.kind) {
    case GenScene::chain: doc = gen_chain(o); break;
    case GenScene::fourbar: doc = gen_fourbar(o); break;
    case GenScene::activation: doc = gen_activation(o); break;
    case GenScene::sleigh: doc = gen_sleigh(o); break;
    case GenScene::bead: doc = gen_bead(o); break;
    case GenScene::motorarm: doc = gen_motorarm(o); break;
    case GenScene::ring: doc = gen_ring(o); break;
  }
  fest::write_output("-", fest::formats::write_json(doc));
  return 0;
}

}  // namespace fest::lmfsim_tool
