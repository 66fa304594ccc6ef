#include "lmfsim/scene_json.hpp"

#include <cmath>
#include <limits>
#include <functional>
#include <set>

#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::lmfsim {

using fest::bad_input;
using nlohmann::json;

namespace {

// Checks that an object only has the allowed keys.
void allow(const json& j, const std::string& where, std::initializer_list<const char*> keys) {
  if (!j.is_object()) throw bad_input("{}: expected an object", where);
  std::set<std::string> ok(keys.begin(), keys.end());
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!ok.count(it.key())) throw bad_input("{}: unknown field '{}'", where, quoted_bytes(it.key()));
}

double num(const json& j, const std::string& where) {
  if (!j.is_number()) throw bad_input("{}: expected a number", where);
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw bad_input("{}: not a finite number", where);
  return v;
}

double num_or(const json& o, const char* key, double def, const std::string& where) {
  return o.contains(key) ? num(o.at(key), where + "." + key) : def;
}

Vec3 vec3(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3) throw bad_input("{}: expected [x, y, z]", where);
  return {num(j[0], where), num(j[1], where), num(j[2], where)};
}

Vec3 vec3_or(const json& o, const char* key, const Vec3& def, const std::string& where) {
  return o.contains(key) ? vec3(o.at(key), where + "." + key) : def;
}

std::string str(const json& j, const std::string& where) {
  if (!j.is_string()) throw bad_input("{}: expected a string", where);
  return j.get<std::string>();
}

bool boolean(const json& j, const std::string& where) {
  if (!j.is_boolean()) throw bad_input("{}: expected true or false", where);
  return j.get<bool>();
}

// A number, or {"keys": [[t, v], ...]}.
Signal signal(const json& j, const std::string& where) {
  Signal s;
  if (j.is_number()) {
    s.value = num(j, where);
    return s;
  }
  allow(j, where, {"keys"});
  if (!j.contains("keys")) throw bad_input("{}: expected a number or {{\"keys\": [[t, value], ...]}}", where);
  const json& keys = j["keys"];
  if (!keys.is_array() || keys.empty()) throw bad_input("{}.keys: expected [[t, value], ...]", where);
  std::vector<double> t, y;
  for (const json& k : keys) {
    if (!k.is_array() || k.size() != 2) throw bad_input("{}.keys: expected [t, value] pairs", where);
    t.push_back(num(k[0], where));
    y.push_back(num(k[1], where));
  }
  s.keys = Spline(t, y);
  return s;
}

// [x, y, z] or {"keys": [[t, x, y, z], ...]}.
Signal3 signal3(const json& j, const std::string& where) {
  Signal3 s;
  if (j.is_array()) {
    const Vec3 v = vec3(j, where);
    for (int k = 0; k < 3; ++k) s.c[static_cast<std::size_t>(k)].value = v[k];
    return s;
  }
  // {"keys": ...} is the caller's (keyed3); any other object would silently be zero.
  throw bad_input("{}: expected [x, y, z] or {{\"keys\": [[t, x, y, z], ...]}}", where);
}

Signal3 keyed3(const json& keys, const std::string& where) {
  if (!keys.is_array() || keys.empty()) throw bad_input("{}: expected [[t, x, y, z], ...]", where);
  std::vector<double> t;
  std::vector<double> y[3];
  for (const json& k : keys) {
    if (!k.is_array() || k.size() != 4) throw bad_input("{}: expected [t, x, y, z] keys", where);
    t.push_back(num(k[0], where));
    for (int c = 0; c < 3; ++c) y[c].push_back(num(k[static_cast<std::size_t>(c) + 1], where));
  }
  Signal3 s;
  for (int c = 0; c < 3; ++c) s.c[static_cast<std::size_t>(c)].keys = Spline(t, y[c]);
  return s;
}

Shape shape(const json& j, const std::string& where) {
  allow(j, where, {"box", "sphere", "cylinder", "rod"});
  if (j.size() != 1) throw bad_input("{}: expected exactly one of box, sphere, cylinder, rod", where);
  Shape s;
  if (j.contains("box")) {
    s.kind = Shape::Kind::box;
    s.dims = vec3(j["box"], where + ".box");
  } else if (j.contains("sphere")) {
    s.kind = Shape::Kind::sphere;
    s.dims = Vec3(num(j["sphere"], where + ".sphere"), 0, 0);
  } else if (j.contains("cylinder")) {
    const json& c = j["cylinder"];
    if (!c.is_array() || c.size() != 2) throw bad_input("{}.cylinder: expected [r, length]", where);
    s.kind = Shape::Kind::cylinder;
    s.dims = Vec3(num(c[0], where), num(c[1], where), 0);
  } else {
    s.kind = Shape::Kind::rod;
    s.dims = Vec3(num(j["rod"], where + ".rod"), 0, 0);
  }
  if (!(s.dims.maxCoeff() > 0) || s.dims.minCoeff() < 0) throw bad_input("{}: sizes must be positive", where);
  return s;
}

int body_ref(const json& j, const std::string& where, const std::vector<Body>& bodies) {
  const std::string name = str(j, where);
  if (name == "world") return kWorld;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  throw bad_input("{}: unknown body '{}'", where, quoted_bytes(name));
}

ConstraintType constraint_type(const std::string& s, const std::string& where) {
  static const std::pair<const char*, ConstraintType> table[] = {
      {"ball", ConstraintType::ball}, {"hinge", ConstraintType::hinge},
      {"axis_parallel", ConstraintType::axis_parallel}, {"slider", ConstraintType::slider},
      {"weld", ConstraintType::weld}, {"distance", ConstraintType::distance},
      {"point_on_plane", ConstraintType::point_on_plane}, {"point_on_line", ConstraintType::point_on_line},
      {"point_on_circle", ConstraintType::point_on_circle}, {"path", ConstraintType::path},
      {"motor", ConstraintType::motor}, {"knife_edge", ConstraintType::knife_edge}};
  for (const auto& [name, t] : table)
    if (s == name) return t;
  throw bad_input("{}: unknown constraint type '{}'", where, quoted_bytes(s));
}

void read_sim(const json& j, SimSettings& sim) {
  allow(j, "sim", {"t_end", "dt", "every", "integrator", "stab", "solver", "formulation", "kappa", "omega0", "zeta",
                   "svd_tol", "max_violation", "rtol", "atol"});
  sim.t_end = num_or(j, "t_end", sim.t_end, "sim");
  sim.dt = num_or(j, "dt", sim.dt, "sim");
  if (j.contains("every")) {
    const double e = num(j["every"], "sim.every");
    // Bounded before the conversion: an int cannot hold 1.7e95 (undefined; fuzz_lmfsim_scene).
    if (e != std::floor(e) || e < 1 || e > std::numeric_limits<int>::max())
      throw bad_input("sim.every: expected a whole number from 1 to {}", std::numeric_limits<int>::max());
    sim.every = static_cast<int>(e);
  }
  if (j.contains("integrator")) {
    const std::string s = str(j["integrator"], "sim.integrator");
    if (s == "euler") sim.integrator = Integrator::euler;
    else if (s == "symplectic") sim.integrator = Integrator::symplectic;
    else if (s == "rk4") sim.integrator = Integrator::rk4;
    else if (s == "rk45") sim.integrator = Integrator::rk45;
    else throw bad_input("sim.integrator: unknown integrator '{}'", quoted_bytes(s));
  }
  if (j.contains("stab")) {
    const json& st = j["stab"];
    allow(st, "sim.stab", {"mode", "alpha", "beta"});
    if (st.contains("mode")) {
      const std::string s = str(st["mode"], "sim.stab.mode");
      if (s == "none") sim.stab = Stabilization::none;
      else if (s == "baumgarte") sim.stab = Stabilization::baumgarte;
      else if (s == "force") sim.stab = Stabilization::force;
      else if (s == "project") sim.stab = Stabilization::project;
      else throw bad_input("sim.stab.mode: unknown mode '{}'", quoted_bytes(s));
    }
    sim.alpha = num_or(st, "alpha", sim.alpha, "sim.stab");
    sim.beta = num_or(st, "beta", sim.beta, "sim.stab");
  }
  if (j.contains("solver")) {
    const std::string s = str(j["solver"], "sim.solver");
    if (s == "baraff") sim.solver = SolverKind::baraff;
    else if (s == "dense") sim.solver = SolverKind::dense;
    else throw bad_input("sim.solver: unknown solver '{}'", quoted_bytes(s));
  }
  if (j.contains("formulation")) {
    const std::string s = str(j["formulation"], "sim.formulation");
    if (s == "lmf") sim.formulation = Formulation::lmf;
    else if (s == "penalty") sim.formulation = Formulation::penalty;
    else throw bad_input("sim.formulation: unknown formulation '{}'", quoted_bytes(s));
  }
  sim.kappa = num_or(j, "kappa", sim.kappa, "sim");
  sim.omega0 = num_or(j, "omega0", sim.omega0, "sim");
  sim.zeta = num_or(j, "zeta", sim.zeta, "sim");
  sim.svd_tol = num_or(j, "svd_tol", sim.svd_tol, "sim");
  sim.max_violation = num_or(j, "max_violation", sim.max_violation, "sim");
  sim.rtol = num_or(j, "rtol", sim.rtol, "sim");
  sim.atol = num_or(j, "atol", sim.atol, "sim");
}

}  // namespace

Scene scene_from_json(const json& doc, const MeshLoader& mesh_loader) {
  allow(doc, "scene", {"gravity", "length_scale", "bodies", "constraints", "forces", "events", "sim"});
  Scene sc;
  sc.gravity = vec3_or(doc, "gravity", sc.gravity, "scene");
  sc.length_scale = num_or(doc, "length_scale", -1, "scene");
  if (!doc.contains("bodies") || !doc["bodies"].is_array() || doc["bodies"].empty())
    throw bad_input("scene: 'bodies' must be a non-empty array");
  int idx = 0;
  for (const json& jb : doc["bodies"]) {
    const std::string where = "bodies[" + std::to_string(idx++) + "]";
    allow(jb, where, {"name", "type", "mass", "shape", "inertia", "mesh", "density", "fixed", "pos", "quat", "vel", "omega"});
    Body b;
    if (!jb.contains("name")) throw bad_input("{}: missing 'name'", where);
    b.name = str(jb["name"], where + ".name");
    const std::string type = jb.contains("type") ? str(jb["type"], where + ".type") : "rigid";
    if (type == "particle") b.kind = BodyKind::particle;
    else if (type == "rigid") b.kind = BodyKind::rigid;
    else throw bad_input("{}.type: expected particle or rigid, got '{}'", where, quoted_bytes(type));
    b.fixed = jb.contains("fixed") && boolean(jb["fixed"], where + ".fixed");
    b.pos = vec3_or(jb, "pos", b.pos, where);
    b.vel = vec3_or(jb, "vel", b.vel, where);
    b.omega = vec3_or(jb, "omega", b.omega, where);
    if (jb.contains("quat")) {
      const json& q = jb["quat"];
      if (!q.is_array() || q.size() != 4) throw bad_input("{}.quat: expected [w, x, y, z]", where);
      b.quat = Quat(num(q[0], where), num(q[1], where), num(q[2], where), num(q[3], where));
      const double n = b.quat.norm();
      if (std::abs(n - 1) > 1e-6) throw bad_input("{}.quat: norm {} is not 1 (quaternions must be unit)", where, n);
    }
    b.mass = num_or(jb, "mass", jb.contains("mesh") ? 0.0 : 1.0, where);
    if (jb.contains("mesh")) {
      if (b.kind != BodyKind::rigid) throw bad_input("{}: a mesh needs a rigid body", where);
      b.shape.kind = Shape::Kind::mesh;
      mesh_loader(str(jb["mesh"], where + ".mesh"), b.shape.vertices, b.shape.triangles);
      const MassProperties mp = mesh_mass_properties(b.shape.vertices, b.shape.triangles);
      if (!(mp.volume > 0)) throw bad_input("{}.mesh: not a closed, outward-oriented mesh (volume {})", where, mp.volume);
      for (Vec3& v : b.shape.vertices) v -= mp.com;  // re-centred at the COM
      const double density = num_or(jb, "density", 0, where);
      if (jb.contains("density") && jb.contains("mass")) throw bad_input("{}: give mass or density, not both", where);
      if (jb.contains("density")) b.mass = density * mp.volume;
      if (!(b.mass > 0)) throw bad_input("{}: mass {} must be positive (mass or density)", where, b.mass);
      b.inertia = mp.inertia * (b.mass / mp.volume);
    } else if (jb.contains("density")) {
      throw bad_input("{}: density needs a mesh", where);
    }
    if (jb.contains("shape")) b.shape = shape(jb["shape"], where + ".shape");
    if (b.kind == BodyKind::rigid && !jb.contains("mesh")) {
      const json inertia = jb.contains("inertia") ? jb["inertia"] : json("auto");
      if (inertia.is_string()) {
        if (inertia.get<std::string>() != "auto") throw bad_input("{}.inertia: expected \"auto\" or a 3x3 matrix", where);
        if (b.shape.kind == Shape::Kind::none) throw bad_input("{}: inertia \"auto\" needs a shape", where);
        b.inertia = shape_inertia(b.shape, b.mass);
      } else {
        if (!inertia.is_array() || inertia.size() != 3) throw bad_input("{}.inertia: expected a 3x3 matrix", where);
        for (int r = 0; r < 3; ++r) {
          const Vec3 row = vec3(inertia[static_cast<std::size_t>(r)], where + ".inertia");
          b.inertia.row(r) = row.transpose();
        }
      }
    }
    sc.bodies.push_back(std::move(b));
  }
  idx = 0;
  if (doc.contains("constraints")) {
    if (!doc["constraints"].is_array()) throw bad_input("scene: 'constraints' must be an array");
    for (const json& jc : doc["constraints"]) {
      const std::string where = "constraints[" + std::to_string(idx) + "]";
      allow(jc, where, {"name", "type", "a", "b", "pa", "pb", "axis_a", "axis_b", "axis", "length", "plane", "line",
                        "circle", "keys", "omega", "active"});
      Constraint c;
      c.name = jc.contains("name") ? str(jc["name"], where + ".name") : "c" + std::to_string(idx);
      if (!jc.contains("type")) throw bad_input("{}: missing 'type'", where);
      c.type = constraint_type(str(jc["type"], where + ".type"), where + ".type");
      if (!jc.contains("a")) throw bad_input("{}: missing 'a'", where);
      c.a = body_ref(jc["a"], where + ".a", sc.bodies);
      c.b = jc.contains("b") ? body_ref(jc["b"], where + ".b", sc.bodies) : kWorld;
      c.pa = vec3_or(jc, "pa", c.pa, where);
      c.pb = vec3_or(jc, "pb", c.pb, where);
      const Vec3 axis = vec3_or(jc, "axis", Vec3::UnitZ(), where);
      c.axis_a = vec3_or(jc, "axis_a", axis, where);
      c.axis_b = vec3_or(jc, "axis_b", axis, where);
      c.active = !jc.contains("active") || boolean(jc["active"], where + ".active");
      if (c.type == ConstraintType::distance) {
        if (!jc.contains("length")) throw bad_input("{}: distance needs 'length'", where);
        c.length = num(jc["length"], where + ".length");
      }
      auto curve = [&](const char* key, bool needs_radius) {
        if (!jc.contains(key)) throw bad_input("{}: {} needs '{}'", where, constraint_type_name(c.type), key);
        const json& cj = jc[key];
        if (needs_radius) allow(cj, where + "." + key, {"o", "n", "r"});
        else allow(cj, where + "." + key, {"o", "n", "d"});
        c.origin = vec3_or(cj, "o", Vec3::Zero(), where + "." + key);
        c.direction = vec3_or(cj, cj.contains("d") ? "d" : "n", Vec3::UnitZ(), where + "." + key);
        if (needs_radius) c.radius = num_or(cj, "r", 0, where + "." + key);
      };
      if (c.type == ConstraintType::point_on_plane) curve("plane", false);
      if (c.type == ConstraintType::point_on_line) curve("line", false);
      if (c.type == ConstraintType::point_on_circle) curve("circle", true);
      if (c.type == ConstraintType::path) {
        if (!jc.contains("keys")) throw bad_input("{}: path needs 'keys'", where);
        c.path = keyed3(jc["keys"], where + ".keys");
      }
      if (c.type == ConstraintType::motor) {
        if (!jc.contains("omega")) throw bad_input("{}: motor needs 'omega'", where);
        c.omega = signal(jc["omega"], where + ".omega");
      }
      sc.constraints.push_back(std::move(c));
      ++idx;
    }
  }
  idx = 0;
  if (doc.contains("forces")) {
    if (!doc["forces"].is_array()) throw bad_input("scene: 'forces' must be an array");
    for (const json& jf : doc["forces"]) {
      const std::string where = "forces[" + std::to_string(idx++) + "]";
      allow(jf, where, {"name", "type", "a", "b", "pa", "pb", "k", "d", "rest", "body", "linear", "angular", "force",
                        "torque", "frame", "goal", "kx", "kv", "ki", "active"});
      ForceElement f;
      f.name = jf.contains("name") ? str(jf["name"], where + ".name") : "";
      const std::string type = jf.contains("type") ? str(jf["type"], where + ".type") : "";
      f.active = !jf.contains("active") || boolean(jf["active"], where + ".active");
      f.pa = vec3_or(jf, "pa", f.pa, where);
      f.pb = vec3_or(jf, "pb", f.pb, where);
      if (type == "spring") {
        f.type = ForceType::spring;
        if (!jf.contains("a") || !jf.contains("b")) throw bad_input("{}: spring needs 'a' and 'b'", where);
        f.a = body_ref(jf["a"], where + ".a", sc.bodies);
        f.b = body_ref(jf["b"], where + ".b", sc.bodies);
        f.k = num_or(jf, "k", 0, where);
        f.d = num_or(jf, "d", 0, where);
        f.rest = num_or(jf, "rest", 0, where);
      } else if (type == "drag") {
        f.type = ForceType::drag;
        const std::string body = jf.contains("body") ? str(jf["body"], where + ".body") : "*";
        f.a = body == "*" ? kWorld : body_ref(jf["body"], where + ".body", sc.bodies);
        f.linear = num_or(jf, "linear", 0, where);
        f.angular = num_or(jf, "angular", 0, where);
      } else if (type == "constant" || type == "pid") {
        f.type = type == "pid" ? ForceType::pid : ForceType::constant;
        if (!jf.contains("body")) throw bad_input("{}: {} needs 'body'", where, type);
        f.a = body_ref(jf["body"], where + ".body", sc.bodies);
        if (f.a == kWorld) throw bad_input("{}: {} needs a body, not the world", where, type);
        f.force = vec3_or(jf, "force", f.force, where);
        f.torque = vec3_or(jf, "torque", f.torque, where);
        if (jf.contains("frame")) {
          const std::string fr = str(jf["frame"], where + ".frame");
          if (fr != "body" && fr != "world") throw bad_input("{}.frame: expected body or world", where);
          f.body_frame = fr == "body";
        }
        if (f.type == ForceType::pid) {
          if (!jf.contains("goal")) throw bad_input("{}: pid needs 'goal'", where);
          const json& g = jf["goal"];
          f.goal = g.is_object() && g.contains("keys") ? keyed3(g["keys"], where + ".goal.keys") : signal3(g, where + ".goal");
          f.kx = vec3_or(jf, "kx", f.kx, where);
          f.kv = vec3_or(jf, "kv", f.kv, where);
          f.ki = vec3_or(jf, "ki", f.ki, where);
        }
      } else {
        throw bad_input("{}.type: unknown force type '{}' (spring, drag, constant, pid)", where, quoted_bytes(type));
      }
      sc.forces.push_back(std::move(f));
    }
  }
  idx = 0;
  if (doc.contains("events")) {
    if (!doc["events"].is_array()) throw bad_input("scene: 'events' must be an array");
    for (const json& je : doc["events"]) {
      const std::string where = "events[" + std::to_string(idx++) + "]";
      allow(je, where, {"t", "action", "target", "value"});
      Event e;
      e.t = num_or(je, "t", 0, where);
      const std::string a = je.contains("action") ? str(je["action"], where + ".action") : "";
      if (a == "activate") e.action = EventAction::activate;
      else if (a == "deactivate") e.action = EventAction::deactivate;
      else if (a == "set") e.action = EventAction::set;
      else if (a == "set_param") e.action = EventAction::set_param;
      else throw bad_input("{}.action: unknown action '{}'", where, quoted_bytes(a));
      if (!je.contains("target")) throw bad_input("{}: missing 'target'", where);
      e.target = str(je["target"], where + ".target");
      if (je.contains("value")) {
        const json& v = je["value"];
        if (v.is_number()) e.value.push_back(num(v, where + ".value"));
        else if (v.is_array()) for (const json& x : v) e.value.push_back(num(x, where + ".value"));
        else throw bad_input("{}.value: expected a number or an array", where);
      }
      sc.events.push_back(std::move(e));
    }
  }
  if (doc.contains("sim")) read_sim(doc["sim"], sc.sim);
  return sc;
}

void write_state(json& doc, const Scene& scene, const std::vector<Vec3>& pos, const std::vector<Quat>& quat,
                 const std::vector<Vec3>& vel, const std::vector<Vec3>& omega) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    json& jb = doc["bodies"][i];
    jb["pos"] = {pos[i].x(), pos[i].y(), pos[i].z()};
    jb["vel"] = {vel[i].x(), vel[i].y(), vel[i].z()};
    if (scene.bodies[i].kind == BodyKind::rigid) {
      jb["quat"] = {quat[i].w(), quat[i].x(), quat[i].y(), quat[i].z()};
      jb["omega"] = {omega[i].x(), omega[i].y(), omega[i].z()};
    }
  }
}

}  // namespace fest::lmfsim
