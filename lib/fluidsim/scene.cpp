#include "fluidsim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "core/closest_word.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::fluidsim {

using nlohmann::json;

namespace {

struct Parser {
  std::string where;

  [[noreturn]] void fail(const std::string& what, const std::string& key) const {
    throw bad_input("{} ({}: {})", what, where, key);
  }

  void check_keys(const json& obj, const std::vector<std::string>& allowed, const std::string& path) const {
    if (!obj.is_object()) fail("must be a JSON object", path.empty() ? "scene" : path);
    for (const auto& [key, value] : obj.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string hint = closest_word(key, allowed);
      const std::string full = path.empty() ? key : path + "." + key;
      if (hint.empty())
        throw bad_input("scene key \"{}\" is unknown ({})", quoted_bytes(full, 40), where);
      throw bad_input("scene key \"{}\" is unknown (did you mean \"{}\"?) ({})", quoted_bytes(full, 40), hint, where);
    }
  }

  // A word-valued member (`fallback` when absent).
  std::string word(const json& obj, const char* member, const std::string& fallback, const std::string& path) const {
    if (!obj.contains(member)) return fallback;
    if (!obj[member].is_string()) fail("must be a word (a JSON string)", path + "." + member);
    return obj[member].get<std::string>();
  }

  double number(const json& v, const std::string& key, double lo, double hi, bool lo_open = false) const {
    if (!v.is_number()) fail("must be a number", key);
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail("must be finite", key);
    if (x < lo || x > hi || (lo_open && x == lo)) {
      if (lo_open) fail(fmt::format("must be > {} and <= {}", lo, hi), key);
      fail(fmt::format("must be in [{}, {}]", lo, hi), key);
    }
    return x;
  }

  int integer(const json& v, const std::string& key, int lo, int hi) const {
    if (!v.is_number_integer() && !v.is_number_unsigned()) fail(fmt::format("must be an integer in [{}, {}]", lo, hi), key);
    const long long x = v.get<long long>();
    if (x < lo || x > hi) fail(fmt::format("must be an integer in [{}, {}]", lo, hi), key);
    return static_cast<int>(x);
  }

  std::array<double, 3> vec(const json& v, const std::string& key, int dim, double fill = 0.0) const {
    if (!v.is_array() || static_cast<int>(v.size()) != dim)
      fail(fmt::format("must be an array of {} numbers", dim), key);
    std::array<double, 3> out{fill, fill, fill};
    for (int a = 0; a < dim; ++a) out[a] = number(v[a], key, -1e30, 1e30);
    return out;
  }
};

}  // namespace

Layout Scene::layout() const {
  double hh = h;
  if (hh == 0.0) {
    int nmax = 0;
    bool closed_max = true;
    for (int a = 0; a < dim; ++a)
      if (dims[a] > nmax) {
        nmax = dims[a];
        closed_max = bc[a] == Boundary::closed;
      }
    hh = 1.0 / (closed_max ? nmax + 1 : nmax);
  }
  return Layout::make(dim, dims, bc, hh);
}

Scene parse_scene(const json& doc, const std::string& where) {
  Parser p{where};
  Scene s;
  p.check_keys(doc, {"dims", "h", "bc", "no_slip", "frame_dt", "interp", "frames", "viscosity", "substeps", "scalars",
                     "forces", "init"},
               "");
  if (!doc.contains("dims")) throw bad_input("scene needs \"dims\" ({})", where);
  const json& d = doc["dims"];
  if (!d.is_array() || (d.size() != 2 && d.size() != 3)) p.fail("dims must be 2 or 3 integers in [3, 1024]", "dims");
  s.dim = static_cast<int>(d.size());
  for (int a = 0; a < s.dim; ++a) {
    if (!d[a].is_number_integer() || d[a].get<long long>() < 3 || d[a].get<long long>() > 1024)
      p.fail("dims must be 2 or 3 integers in [3, 1024]", "dims");
    s.dims[a] = d[a].get<int>();
  }
  if (doc.contains("h")) s.h = p.number(doc["h"], "h", 0.0, 1e9, true);
  if (doc.contains("bc")) {
    const json& b = doc["bc"];
    auto one = [&](const json& v) {
      if (v == "closed") return Boundary::closed;
      if (v == "periodic") return Boundary::periodic;
      p.fail("must be \"closed\" or \"periodic\"", "bc");
    };
    if (b.is_string()) {
      s.bc.fill(one(b));
    } else if (b.is_array() && static_cast<int>(b.size()) == s.dim) {
      for (int a = 0; a < s.dim; ++a) s.bc[a] = one(b[a]);
    } else {
      p.fail("must be \"closed\", \"periodic\" or one of them per axis", "bc");
    }
  }
  if (doc.contains("no_slip")) {
    if (!doc["no_slip"].is_boolean()) p.fail("must be true or false", "no_slip");
    s.no_slip = doc["no_slip"].get<bool>();
  }
  if (doc.contains("frame_dt")) s.frame_dt = p.number(doc["frame_dt"], "frame_dt", 0.0, 1e6, true);
  if (doc.contains("interp")) s.interp = p.integer(doc["interp"], "interp", 1, 1000);
  if (doc.contains("frames")) s.frames = p.integer(doc["frames"], "frames", 1, 10000000);
  if (doc.contains("viscosity")) s.viscosity = p.number(doc["viscosity"], "viscosity", 0.0, 1e6);
  if (doc.contains("substeps")) s.substeps = p.integer(doc["substeps"], "substeps", 1, 64);

  const Layout layout = s.layout();
  auto check_point = [&](const std::array<double, 3>& q, const std::string& key) {
    for (int a = 0; a < s.dim; ++a)
      if (q[a] < 0 || q[a] > layout.size[a] - 1)
        p.fail(fmt::format("position {} is outside the grid [0, {}]", q[a], layout.size[a] - 1), key);
  };

  if (doc.contains("scalars")) {
    const json& arr = doc["scalars"];
    if (!arr.is_array()) p.fail("must be an array", "scalars");
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string path = fmt::format("scalars[{}]", i);
      p.check_keys(arr[i], {"name", "kappa", "alpha", "init", "sources"}, path);
      ScalarSpec sc;
      if (arr[i].contains("name")) {
        if (!arr[i]["name"].is_string() || arr[i]["name"].get<std::string>().empty() ||
            arr[i]["name"].get<std::string>().find_first_of(" ,:=\n") != std::string::npos)
          p.fail("must be a name without spaces, commas, colons or '='", path + ".name");
        sc.name = arr[i]["name"].get<std::string>();
      }
      for (const auto& other : s.scalars)
        if (other.name == sc.name || sc.name == "velocity") p.fail("names a scalar twice", path + ".name");
      if (arr[i].contains("kappa")) sc.kappa = p.number(arr[i]["kappa"], path + ".kappa", 0.0, 1e6);
      if (arr[i].contains("alpha")) sc.alpha = p.number(arr[i]["alpha"], path + ".alpha", 0.0, 1e6);
      if (arr[i].contains("init")) sc.init = p.number(arr[i]["init"], path + ".init", -1e30, 1e30);
      if (arr[i].contains("sources")) {
        const json& srcs = arr[i]["sources"];
        if (!srcs.is_array()) p.fail("must be an array", path + ".sources");
        for (std::size_t k = 0; k < srcs.size(); ++k) {
          const std::string sp = fmt::format("{}.sources[{}]", path, k);
          const json& j = srcs[k];
          p.check_keys(j, {"shape", "min", "max", "centre", "center", "radius", "rate", "velocity", "start", "end"}, sp);
          Source src;
          const std::string shape = p.word(j, "shape", "box", sp);
          if (shape == "box") {
            src.shape = Source::Shape::box;
            if (!j.contains("min") || !j.contains("max")) p.fail("a box needs \"min\" and \"max\"", sp);
            src.min = p.vec(j["min"], sp + ".min", s.dim);
            src.max = p.vec(j["max"], sp + ".max", s.dim);
            for (int a = 0; a < s.dim; ++a)
              if (src.min[a] > src.max[a]) p.fail("min must not exceed max", sp);
            // Wholly outside: an error; partly: clipped with a warning.
            bool outside = false, partly = false;
            for (int a = 0; a < s.dim; ++a) {
              const double hi = layout.size[a] - 1;
              if (src.max[a] < 0 || src.min[a] > hi) outside = true;
              if (src.min[a] < 0 || src.max[a] > hi) partly = true;
              src.min[a] = std::max(src.min[a], 0.0);
              src.max[a] = std::min(src.max[a], hi);
            }
            if (outside) p.fail("source lies outside the grid", sp);
            if (partly) s.warnings.push_back(fmt::format("source {} is partly outside the grid; clipped", sp));
          } else if (shape == "sphere" || shape == "gauss") {
            src.shape = shape == "sphere" ? Source::Shape::sphere : Source::Shape::gauss;
            const char* ck = j.contains("centre") ? "centre" : "center";
            if (!j.contains(ck)) p.fail("needs \"centre\"", sp);
            src.centre = p.vec(j[ck], sp + "." + ck, s.dim);
            check_point(src.centre, sp + "." + ck);
            if (j.contains("radius")) src.radius = p.number(j["radius"], sp + ".radius", 0.0, 1e6, true);
          } else {
            p.fail("must be \"box\", \"sphere\" or \"gauss\"", sp + ".shape");
          }
          if (j.contains("rate")) src.rate = p.number(j["rate"], sp + ".rate", -1e12, 1e12);
          if (j.contains("velocity")) {
            src.jet = true;
            src.velocity = p.vec(j["velocity"], sp + ".velocity", s.dim);
          }
          if (j.contains("start")) src.start = p.number(j["start"], sp + ".start", 0.0, 1e12);
          if (j.contains("end")) src.end = p.number(j["end"], sp + ".end", 0.0, 1e12);
          sc.sources.push_back(src);
        }
      }
      s.scalars.push_back(sc);
    }
  } else {
    s.scalars.push_back(ScalarSpec{});
  }

  if (doc.contains("forces")) {
    const json& arr = doc["forces"];
    if (!arr.is_array()) p.fail("must be an array", "forces");
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string path = fmt::format("forces[{}]", i);
      const json& j = arr[i];
      p.check_keys(j, {"type", "scalar", "beta", "ambient", "up", "value", "centre", "center", "strength", "radius"},
                   path);
      Force f;
      f.up = s.dim == 2 ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{0, 0, 1};
      const std::string type = p.word(j, "type", "", path);
      if (type == "buoyancy") {
        f.type = Force::Type::buoyancy;
        f.scalar = p.word(j, "scalar", s.scalars.front().name, path);
        bool known = false;
        for (const auto& sc : s.scalars) known = known || sc.name == f.scalar;
        if (!known) p.fail(fmt::format("names no scalar \"{}\"", quoted_bytes(f.scalar)), path + ".scalar");
        if (j.contains("beta")) f.beta = p.number(j["beta"], path + ".beta", -1e9, 1e9);
        if (j.contains("ambient")) f.ambient = p.number(j["ambient"], path + ".ambient", -1e12, 1e12);
      } else if (type == "gravity" || type == "constant") {
        f.type = type == "gravity" ? Force::Type::gravity : Force::Type::constant;
        if (!j.contains("value")) p.fail("needs \"value\"", path);
        f.value = p.vec(j["value"], path + ".value", s.dim);
      } else if (type == "vortex") {
        f.type = Force::Type::vortex;
        const char* ck = j.contains("centre") ? "centre" : "center";
        if (!j.contains(ck)) p.fail("needs \"centre\"", path);
        f.centre = p.vec(j[ck], path + "." + ck, s.dim);
        if (j.contains("strength")) f.strength = p.number(j["strength"], path + ".strength", -1e9, 1e9);
        if (j.contains("radius")) f.radius = p.number(j["radius"], path + ".radius", 0.0, 1e6, true);
      } else {
        p.fail("must be \"buoyancy\", \"gravity\", \"constant\" or \"vortex\"", path + ".type");
      }
      if (j.contains("up")) f.up = p.vec(j["up"], path + ".up", s.dim);
      s.forces.push_back(f);
    }
  }

  if (doc.contains("init")) {
    const json& in = doc["init"];
    if (in.is_string()) {
      s.init.kind = in.get<std::string>();
      const std::string& v = s.init.kind;
      const auto ends = [&](const char* e) { return v.size() > std::strlen(e) && v.compare(v.size() - std::strlen(e), std::string::npos, e) == 0; };
      if (ends(".vti") || ends(".nrrd")) {
        // A frame written by fluidsim (VTI, or an NRRD frame): the tool reads it.
        s.init.file = v;
        s.init.kind = "file";
      }
    } else if (in.is_object() && in.contains("noise")) {
      p.check_keys(in, {"noise"}, "init");
      p.check_keys(in["noise"], {"seed", "amp"}, "init.noise");
      s.init.kind = "noise";
      if (in["noise"].contains("seed")) s.init.seed = static_cast<unsigned>(p.integer(in["noise"]["seed"], "init.noise.seed", 0, 1 << 30));
      if (in["noise"].contains("amp")) s.init.amp = p.number(in["noise"]["amp"], "init.noise.amp", 0.0, 1e6);
    } else {
      p.fail("must be \"zero\", \"taylor-green\", \"abc\" or {\"noise\": {...}}", "init");
    }
    if (s.init.kind != "zero" && s.init.kind != "taylor-green" && s.init.kind != "abc" && s.init.kind != "noise" &&
        s.init.kind != "file")
      p.fail("must be \"zero\", \"taylor-green\", \"abc\", {\"noise\": {...}} or a .vti/.nrrd frame file", "init");
  }
  return s;
}

void add_plume(Scene& scene, const Source& source) {
  ScalarSpec s;
  s.sources = {source};
  scene.scalars = {s};
  Force f;
  f.type = Force::Type::buoyancy;
  f.scalar = "density";
  f.beta = 1.0;
  scene.forces = {f};
}

}  // namespace fest::fluidsim
