// The case file codec (docs/lbmsim.md "Case file"): JSON <-> Case, with unit conversion
// (section "Units") and the checks that keep unstable or inconsistent cases out.
#include "lbm/case_json.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/closest_word.hpp"
#include "core/error.hpp"

namespace fest::lbm {

using nlohmann::json;

namespace {

struct Ctx {
  std::string where;
};

void check_keys(const json& obj, const std::string& path, const std::vector<std::string>& allowed, const Ctx& ctx) {
  if (!obj.is_object()) throw bad_input("case key \"{}\" must be an object ({})", path, ctx.where);
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
    const std::string full = path.empty() ? it.key() : path + "." + it.key();
    const std::string hint = closest_word(it.key(), allowed);
    if (hint.empty()) throw bad_input("case key \"{}\" is unknown ({})", full, ctx.where);
    throw bad_input("case key \"{}\" is unknown (did you mean \"{}\"?) ({})", full,
                    path.empty() ? hint : path + "." + hint, ctx.where);
  }
}

double number(const json& v, const std::string& path, const Ctx& ctx) {
  if (!v.is_number()) throw bad_input("case key \"{}\" must be a number ({})", path, ctx.where);
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw bad_input("case key \"{}\" must be finite ({})", path, ctx.where);
  return d;
}

double positive(const json& v, const std::string& path, const Ctx& ctx) {
  const double d = number(v, path, ctx);
  if (!(d > 0)) throw bad_input("case key \"{}\" = {} must be positive ({})", path, d, ctx.where);
  return d;
}

long integer(const json& v, const std::string& path, long lo, long hi, const Ctx& ctx) {
  if (!v.is_number_integer() && !(v.is_number() && std::floor(v.get<double>()) == v.get<double>()))
    throw bad_input("case key \"{}\" must be an integer ({})", path, ctx.where);
  const double d = v.get<double>();
  if (d < lo || d > hi) throw bad_input("case key \"{}\" = {} is outside [{}, {}] ({})", path, d, lo, hi, ctx.where);
  return static_cast<long>(d);
}

std::array<double, 3> vec(const json& v, const std::string& path, int dim, const Ctx& ctx) {
  if (!v.is_array() || static_cast<int>(v.size()) != dim)
    throw bad_input("case key \"{}\" must be an array of {} numbers ({})", path, dim, ctx.where);
  std::array<double, 3> r{0, 0, 0};
  for (int a = 0; a < dim; ++a) r[a] = number(v[a], path + "[" + std::to_string(a) + "]", ctx);
  return r;
}

std::string str(const json& v, const std::string& path, const Ctx& ctx) {
  if (!v.is_string()) throw bad_input("case key \"{}\" must be a string ({})", path, ctx.where);
  return v.get<std::string>();
}

std::uint8_t flag_id(const json& v, const std::string& path, const Ctx& ctx) {
  const long f = integer(v, path, 1, 254, ctx);
  if (f >= 2 && f <= 5)
    throw bad_input("case key \"{}\" = {}: flags 2..5 (inlet, outlet, moving, slip) are set on faces, not shapes ({})",
                    path, f, ctx.where);
  return static_cast<std::uint8_t>(f);
}

Face parse_face(const json& v, const std::string& path, int dim, const Ctx& ctx) {
  Face f;
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "periodic") f.kind = Face::Kind::periodic;
    else if (s == "wall") f.kind = Face::Kind::wall;
    else if (s == "slip") throw bad_input("case key \"{}\": slip faces are not supported in this version ({})", path, ctx.where);
    else {
      const std::string hint = closest_word(s, {"periodic", "wall", "moving", "velocity", "pressure"});
      throw bad_input("case key \"{}\" = \"{}\" is not a face type{} ({})", path, s,
                      hint.empty() ? "" : " (did you mean \"" + hint + "\"?)", ctx.where);
    }
    return f;
  }
  check_keys(v, path, {"moving", "velocity", "pressure", "wall", "periodic"}, ctx);
  if (v.size() != 1) throw bad_input("case key \"{}\" must hold exactly one face type ({})", path, ctx.where);
  const std::string kind = v.begin().key();
  const json& p = v.begin().value();
  const std::string pp = path + "." + kind;
  if (kind == "wall" || kind == "periodic") {
    f.kind = kind == "wall" ? Face::Kind::wall : Face::Kind::periodic;
  } else if (kind == "moving") {
    check_keys(p, pp, {"u"}, ctx);
    f.kind = Face::Kind::moving;
    if (!p.contains("u")) throw bad_input("case key \"{}.u\" is required ({})", pp, ctx.where);
    f.u = vec(p["u"], pp + ".u", dim, ctx);
  } else if (kind == "velocity") {
    check_keys(p, pp, {"u", "profile"}, ctx);
    f.kind = Face::Kind::velocity;
    if (!p.contains("u")) throw bad_input("case key \"{}.u\" is required ({})", pp, ctx.where);
    if (p["u"].is_array()) {
      f.u = vec(p["u"], pp + ".u", dim, ctx);
      f.u_vector = true;
    } else {
      f.speed = number(p["u"], pp + ".u", ctx);
    }
    if (p.contains("profile")) {
      const std::string pr = str(p["profile"], pp + ".profile", ctx);
      if (pr == "uniform") f.profile = Face::Profile::uniform;
      else if (pr == "parabolic") f.profile = Face::Profile::parabolic;
      else throw bad_input("case key \"{}.profile\" = \"{}\" must be uniform or parabolic ({})", pp, pr, ctx.where);
    }
  } else {  // pressure
    check_keys(p, pp, {"rho"}, ctx);
    f.kind = Face::Kind::pressure;
    if (p.contains("rho")) f.rho = positive(p["rho"], pp + ".rho", ctx);
  }
  return f;
}

Shape parse_shape(const json& v, const std::string& path, int dim, const Ctx& ctx) {
  check_keys(v, path, {"box", "sphere", "cylinder"}, ctx);
  if (v.size() != 1) throw bad_input("case key \"{}\" must hold exactly one shape ({})", path, ctx.where);
  Shape s;
  const std::string kind = v.begin().key();
  const json& p = v.begin().value();
  const std::string pp = path + "." + kind;
  if (kind == "box") {
    check_keys(p, pp, {"min", "max", "flag"}, ctx);
    s.kind = Shape::Kind::box;
    if (!p.contains("min") || !p.contains("max")) throw bad_input("case key \"{}\" needs min and max ({})", pp, ctx.where);
    s.lo = vec(p["min"], pp + ".min", dim, ctx);
    s.hi = vec(p["max"], pp + ".max", dim, ctx);
    if (dim == 2) s.lo[2] = -1e300, s.hi[2] = 1e300;
  } else {
    check_keys(p, pp, {"center", "radius", "axis", "flag"}, ctx);
    s.kind = kind == "sphere" ? Shape::Kind::sphere : Shape::Kind::cylinder;
    if (!p.contains("center") || !p.contains("radius"))
      throw bad_input("case key \"{}\" needs center and radius ({})", pp, ctx.where);
    s.center = vec(p["center"], pp + ".center", dim, ctx);
    s.radius = positive(p["radius"], pp + ".radius", ctx);
    if (p.contains("axis")) {
      const std::string a = str(p["axis"], pp + ".axis", ctx);
      if (a != "x" && a != "y" && a != "z") throw bad_input("case key \"{}.axis\" must be x, y or z ({})", pp, ctx.where);
      s.axis = a[0] - 'x';
    }
  }
  if (p.contains("flag")) s.flag = flag_id(p["flag"], pp + ".flag", ctx);
  return s;
}

void parse_geometry_item(const json& v, const std::string& path, Case& c, const Ctx& ctx) {
  if (v.is_object() && v.contains("mask")) {
    check_keys(v, path, {"mask"}, ctx);
    c.mask_file = str(v["mask"], path + ".mask", ctx);
    if (c.dim != 2) throw bad_input("case key \"{}.mask\" is for 2-D cases; use \"flags\" in 3-D ({})", path, ctx.where);
  } else if (v.is_object() && v.contains("flags")) {
    check_keys(v, path, {"flags"}, ctx);
    c.flags_file = str(v["flags"], path + ".flags", ctx);
  } else if (v.is_object() && v.contains("mesh")) {
    check_keys(v, path, {"mesh", "fit", "margin", "region", "flag"}, ctx);
    MeshGeometry m;
    m.file = str(v["mesh"], path + ".mesh", ctx);
    if (c.dim != 3) throw bad_input("case key \"{}.mesh\" needs a 3-D case ({})", path, ctx.where);
    if (v.contains("fit")) {
      const std::string f = str(v["fit"], path + ".fit", ctx);
      if (f != "box" && f != "none") throw bad_input("case key \"{}.fit\" must be box or none ({})", path, ctx.where);
      m.fit_box = f == "box";
    }
    if (v.contains("margin")) {
      m.margin = number(v["margin"], path + ".margin", ctx);
      if (m.margin < 0) throw bad_input("case key \"{}.margin\" must be >= 0 ({})", path, ctx.where);
    }
    if (v.contains("region")) {
      const json& r = v["region"];
      if (!r.is_array() || r.size() != 6)
        throw bad_input("case key \"{}.region\" must be [x0,y0,z0,x1,y1,z1] ({})", path, ctx.where);
      for (int i = 0; i < 6; ++i) m.region[i] = number(r[i], path + ".region", ctx);
    }
    if (v.contains("flag")) m.flag = flag_id(v["flag"], path + ".flag", ctx);
    c.meshes.push_back(m);
  } else {
    c.shapes.push_back(parse_shape(v, path, c.dim, ctx));
  }
}

}  // namespace

Case parse_case(const json& doc, const std::string& where) {
  const Ctx ctx{where};
  Case c;
  check_keys(doc, "", {"lattice", "size", "collision", "re", "u_ref", "l_ref", "faces", "geometry", "force", "init",
                       "steps", "tol", "check_every", "output", "probes", "forces", "units", "curved_walls"}, ctx);
  if (!doc.contains("size")) throw bad_input("case key \"size\" is required ({})", where);
  const json& sz = doc["size"];
  if (!sz.is_array() || (sz.size() != 2 && sz.size() != 3))
    throw bad_input("case key \"size\" must be [nx, ny] or [nx, ny, nz] ({})", where);
  c.dim = static_cast<int>(sz.size());
  for (int a = 0; a < c.dim; ++a) c.size[a] = static_cast<int>(integer(sz[a], "size", 3, 1 << 20, ctx));
  if (static_cast<double>(c.size[0]) * c.size[1] * c.size[2] > 4e9)
    throw bad_input("case key \"size\": {} cells are too many ({})", static_cast<double>(c.size[0]) * c.size[1] * c.size[2], where);
  c.lattice = c.dim == 2 ? LatticeKind::d2q9 : LatticeKind::d3q19;
  if (doc.contains("lattice")) {
    const std::string l = str(doc["lattice"], "lattice", ctx);
    if (l != "d2q9" && l != "d3q19") throw bad_input("case key \"lattice\" = \"{}\" must be d2q9 or d3q19 ({})", l, where);
    if ((l == "d2q9") != (c.dim == 2))
      throw bad_input("case key \"lattice\" = \"{}\" does not fit a size with {} entries ({})", l, c.dim, where);
  }
  if (doc.contains("u_ref")) c.u_ref = positive(doc["u_ref"], "u_ref", ctx);
  if (doc.contains("l_ref")) c.l_ref = positive(doc["l_ref"], "l_ref", ctx);
  if (doc.contains("re")) c.re = positive(doc["re"], "re", ctx);

  if (doc.contains("units")) {
    const json& u = doc["units"];
    check_keys(u, "units", {"dx", "u_phys", "u_lattice", "nu_phys", "rho_phys"}, ctx);
    c.units.physical = true;
    for (const char* k : {"dx", "u_phys", "nu_phys"})
      if (!u.contains(k)) throw bad_input("case key \"units.{}\" is required with physical units ({})", k, where);
    c.units.dx = positive(u["dx"], "units.dx", ctx);
    c.units.u_phys = positive(u["u_phys"], "units.u_phys", ctx);
    c.units.nu_phys = positive(u["nu_phys"], "units.nu_phys", ctx);
    if (u.contains("u_lattice")) c.units.u_lattice = positive(u["u_lattice"], "units.u_lattice", ctx);
    if (u.contains("rho_phys")) c.units.rho_phys = positive(u["rho_phys"], "units.rho_phys", ctx);
    if (!doc.contains("u_ref")) c.u_ref = c.units.u_lattice;
  }

  bool tau_given = false;
  if (doc.contains("collision")) {
    const json& co = doc["collision"];
    check_keys(co, "collision", {"model", "tau", "nu", "lambda", "equilibrium"}, ctx);
    if (co.contains("equilibrium")) {
      const std::string e = str(co["equilibrium"], "collision.equilibrium", ctx);
      if (e != "compressible" && e != "incompressible")
        throw bad_input("case key \"collision.equilibrium\" = \"{}\" must be compressible or incompressible ({})", e, where);
      c.collision.incompressible = e == "incompressible";
    }
    if (co.contains("model")) {
      const std::string m = str(co["model"], "collision.model", ctx);
      if (m == "bgk") c.collision.model = CollisionModel::bgk;
      else if (m == "trt") c.collision.model = CollisionModel::trt;
      else throw bad_input("case key \"collision.model\" = \"{}\" must be bgk or trt ({})", m, where);
    }
    if (co.contains("tau") && co.contains("nu")) throw bad_input("case keys \"collision.tau\" and \"collision.nu\" exclude each other ({})", where);
    if (co.contains("tau")) {
      c.collision.tau = number(co["tau"], "collision.tau", ctx);
      tau_given = true;
    }
    if (co.contains("nu")) {
      const double nu = number(co["nu"], "collision.nu", ctx);
      if (!(nu > 0)) throw bad_input("collision.nu = {} gives no viscosity; need nu > 0 ({})", nu, where);
      c.collision.tau = 3 * nu + 0.5;
      tau_given = true;
    }
    if (co.contains("lambda")) {
      c.collision.lambda = number(co["lambda"], "collision.lambda", ctx);
      if (!(c.collision.lambda > 0)) throw bad_input("collision.lambda = {} must be > 0 ({})", c.collision.lambda, where);
    }
  }
  if (!tau_given) {
    if (c.units.physical) {
      const double nu_lat = c.units.nu_phys * c.units.dt() / (c.units.dx * c.units.dx);
      c.collision.tau = 3 * nu_lat + 0.5;
    } else if (c.re > 0) {
      c.collision.tau = 3 * c.u_ref * c.lref() / c.re + 0.5;
    } else {
      throw bad_input("case needs collision.tau, collision.nu, re or physical units to set the viscosity ({})", where);
    }
  }
  if (!(c.collision.tau > 0.5 + 1e-4))
    throw bad_input("collision.tau = {} gives zero viscosity; need tau > 0.5 ({})", c.collision.tau, where);

  if (doc.contains("faces")) {
    const json& f = doc["faces"];
    std::vector<std::string> names;
    for (int i = 0; i < 2 * c.dim; ++i) names.push_back(face_name(i));
    check_keys(f, "faces", names, ctx);
    for (int i = 0; i < 2 * c.dim; ++i)
      if (f.contains(names[i])) c.faces[i] = parse_face(f[names[i]], "faces." + names[i], c.dim, ctx);
  }
  if (doc.contains("geometry")) {
    const json& g = doc["geometry"];
    if (g.is_array()) {
      for (std::size_t i = 0; i < g.size(); ++i) parse_geometry_item(g[i], "geometry[" + std::to_string(i) + "]", c, ctx);
    } else {
      parse_geometry_item(g, "geometry", c, ctx);
    }
  }
  if (doc.contains("force")) c.force = vec(doc["force"], "force", c.dim, ctx);
  if (doc.contains("init")) {
    const json& in = doc["init"];
    if (in.is_string()) {
      const std::string s = in.get<std::string>();
      if (s != "taylor-green") throw bad_input("case key \"init\" = \"{}\" must be taylor-green or an object ({})", s, where);
      c.init.kind = Init::Kind::taylor_green;
      c.init.amplitude = c.u_ref;
    } else {
      check_keys(in, "init", {"rho", "u", "file"}, ctx);
      if (in.contains("rho")) c.init.rho = positive(in["rho"], "init.rho", ctx);
      if (in.contains("u")) c.init.u = vec(in["u"], "init.u", c.dim, ctx);
      if (in.contains("file")) {
        c.init.kind = Init::Kind::file;
        c.init.file = str(in["file"], "init.file", ctx);
      }
    }
  }
  if (!doc.contains("steps")) throw bad_input("case key \"steps\" is required ({})", where);
  if (doc["steps"].is_string()) {
    if (doc["steps"].get<std::string>() != "steady")
      throw bad_input("case key \"steps\" must be a number or \"steady\" ({})", where);
    c.steady = true;
    c.steps = 10'000'000;
  } else {
    c.steps = integer(doc["steps"], "steps", 0, 2'000'000'000, ctx);
  }
  if (doc.contains("tol")) c.tol = positive(doc["tol"], "tol", ctx);
  if (doc.contains("curved_walls")) {
    const std::string w = str(doc["curved_walls"], "curved_walls", ctx);
    if (w != "halfway" && w != "bouzidi") throw bad_input("case key \"curved_walls\" must be halfway or bouzidi ({})", where);
    c.bouzidi = w == "bouzidi";
  }
  if (doc.contains("check_every")) c.check_every = integer(doc["check_every"], "check_every", 1, 1'000'000'000, ctx);
  if (doc.contains("output")) {
    const json& o = doc["output"];
    check_keys(o, "output", {"every", "fields", "format", "precision", "compress"}, ctx);
    if (o.contains("every")) c.output.every = integer(o["every"], "output.every", 0, 2'000'000'000, ctx);
    if (o.contains("fields")) {
      const json& fl = o["fields"];
      if (!fl.is_array()) throw bad_input("case key \"output.fields\" must be a list of names ({})", where);
      c.output.fields.clear();
      for (const json& f : fl) c.output.fields.push_back(str(f, "output.fields", ctx));
    }
    if (o.contains("format")) {
      c.output.format = str(o["format"], "output.format", ctx);
      if (c.output.format != "vti" && c.output.format != "nrrd" && c.output.format != "stream")
        throw bad_input("case key \"output.format\" must be vti, nrrd or stream ({})", where);
    }
    if (o.contains("precision")) {
      const std::string p = str(o["precision"], "output.precision", ctx);
      if (p != "float32" && p != "float64") throw bad_input("case key \"output.precision\" must be float32 or float64 ({})", where);
      c.output.float64 = p == "float64";
    }
    if (o.contains("compress")) {
      if (!o["compress"].is_boolean()) throw bad_input("case key \"output.compress\" must be true or false ({})", where);
      c.output.compress = o["compress"].get<bool>();
    }
  }
  if (doc.contains("probes")) {
    const json& p = doc["probes"];
    if (!p.is_array()) throw bad_input("case key \"probes\" must be a list of points ({})", where);
    for (std::size_t i = 0; i < p.size(); ++i) c.probes.push_back(vec(p[i], "probes[" + std::to_string(i) + "]", c.dim, ctx));
  }
  if (doc.contains("forces")) {
    const json& f = doc["forces"];
    if (!f.is_array()) throw bad_input("case key \"forces\" must be a list of flag ids ({})", where);
    for (const json& id : f) c.forces.push_back(flag_id(id, "forces", ctx));
  }
  validate_case(c, where);
  return c;
}

json case_to_json(const Case& c) {
  json j;
  j["lattice"] = c.lattice == LatticeKind::d2q9 ? "d2q9" : "d3q19";
  j["size"] = std::vector<int>(c.size.begin(), c.size.begin() + c.dim);
  j["collision"] = {{"model", c.collision.model == CollisionModel::bgk ? "bgk" : "trt"},
                    {"tau", c.collision.tau},
                    {"lambda", c.collision.lambda}};
  if (c.collision.incompressible) j["collision"]["equilibrium"] = "incompressible";
  j["u_ref"] = c.u_ref;
  j["l_ref"] = c.lref();
  json faces;
  for (int i = 0; i < 2 * c.dim; ++i) {
    const Face& f = c.faces[i];
    const std::vector<double> u(f.u.begin(), f.u.begin() + c.dim);
    switch (f.kind) {
      case Face::Kind::periodic: faces[face_name(i)] = "periodic"; break;
      case Face::Kind::wall: faces[face_name(i)] = "wall"; break;
      case Face::Kind::moving: faces[face_name(i)] = {{"moving", {{"u", u}}}}; break;
      case Face::Kind::velocity:
        faces[face_name(i)] = {{"velocity",
                                {{"u", f.u_vector ? json(u) : json(f.speed)},
                                 {"profile", f.profile == Face::Profile::parabolic ? "parabolic" : "uniform"}}}};
        break;
      case Face::Kind::pressure: faces[face_name(i)] = {{"pressure", {{"rho", f.rho}}}}; break;
    }
  }
  j["faces"] = faces;
  j["steps"] = c.steady ? json("steady") : json(c.steps);
  j["force"] = std::vector<double>(c.force.begin(), c.force.begin() + c.dim);
  if (c.bouzidi) j["curved_walls"] = "bouzidi";
  return j;
}

CaseOverride parse_override(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw usage_error("\"{}\" must be key=value", assignment);
  CaseOverride o;
  o.value = assignment.substr(eq + 1);
  const std::string key = assignment.substr(0, eq);
  for (std::size_t begin = 0;;) {
    const std::size_t dot = key.find('.', begin);
    o.path.push_back(key.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
    if (o.path.back().empty()) throw usage_error("\"{}\": empty key part", assignment);
    if (dot == std::string::npos) return o;
    begin = dot + 1;
  }
}

void apply_override(json& doc, const std::string& assignment) { apply_override(doc, parse_override(assignment)); }

void apply_override(json& doc, const CaseOverride& o) {
  json value;
  try {
    value = json::parse(o.value);
  } catch (const json::exception&) {  // also out_of_range: a number beyond double's range
    value = o.value;
  }
  if (!doc.is_object()) throw usage_error("the case is not a JSON object");
  if (o.path.empty()) throw usage_error("an override needs a key");
  json* node = &doc;
  for (std::size_t i = 0; i + 1 < o.path.size(); ++i) {
    json& next = (*node)[o.path[i]];
    if (next.is_null()) next = json::object();
    if (!next.is_object()) throw usage_error("\"{}\" is not an object", o.path[i]);
    node = &next;
  }
  (*node)[o.path.back()] = value;
}

}  // namespace fest::lbm
