#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "ffd/lattice_codec.hpp"

namespace fest::ffd {

namespace {

using nlohmann::json;

Eigen::Vector3d vec3(const json& j, const char* what) {
  if (!j.is_array() || j.size() != 3) throw bad_input("lattice JSON: {} must be an array of 3 numbers", what);
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[static_cast<std::size_t>(i)].is_number()) throw bad_input("lattice JSON: {} must be an array of 3 numbers", what);
    v[i] = j[static_cast<std::size_t>(i)].get<double>();
  }
  return v;
}

Basis basis_of(const json& j) {
  if (!j.is_string()) throw bad_input("lattice JSON: basis names must be strings");
  try {
    return basis_from_name(j.get<std::string>().c_str());
  } catch (const Error& e) {
    throw bad_input("lattice JSON: {}", e.what());
  }
}

}  // namespace

Lattice decode_lattice_json(std::string_view text) {
  json j;
  try {
    j = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw bad_input("lattice JSON: {}", json_failure_words(e.what(), e.byte, text));
  } catch (const json::exception& e) {
    throw bad_input("lattice JSON: {}", json_failure_words(e.what(), 0, text));
  }
  if (!j.is_object()) throw bad_input("lattice JSON: not an object");
  Lattice l;
  if (!j.contains("origin") || !j.contains("axes") || !j.contains("dims"))
    throw bad_input("lattice JSON: needs origin, axes and dims");
  l.origin = vec3(j["origin"], "origin");
  const json& axes = j["axes"];
  if (!axes.is_array() || axes.size() != 3) throw bad_input("lattice JSON: axes must hold 3 vectors");
  for (std::size_t a = 0; a < 3; ++a) l.axes[a] = vec3(axes[a], "an axis");
  const json& dims = j["dims"];
  if (!dims.is_array() || dims.size() != 3) throw bad_input("lattice JSON: dims must be 3 integers");
  for (std::size_t a = 0; a < 3; ++a) {
    if (!dims[a].is_number_integer()) throw bad_input("lattice JSON: dims must be 3 integers");
    const long long d = dims[a].get<long long>();
    if (d < 2 || d > max_axis_points) throw bad_input("lattice JSON: dims[{}] = {} is outside 2..{}", a, d, max_axis_points);
    l.dims[a] = static_cast<int>(d);
  }
  if (j.contains("basis")) {
    const json& b = j["basis"];
    if (b.is_array()) {
      if (b.size() != 3) throw bad_input("lattice JSON: basis array must have 3 names");
      for (std::size_t a = 0; a < 3; ++a) l.basis[a] = basis_of(b[a]);
    } else {
      l.basis.fill(basis_of(b));
    }
  }
  l.displacement.assign(l.size(), Eigen::Vector3d::Zero());
  if (j.contains("displacements") && j.contains("points"))
    throw bad_input("lattice JSON: give displacements or points, not both");
  if (j.contains("displacements")) {
    const json& d = j["displacements"];
    if (!d.is_array()) throw bad_input("lattice JSON: displacements must be an array");
    for (std::size_t r = 0; r < d.size(); ++r) {
      const json& e = d[r];
      if (!e.is_array() || e.size() != 6) throw bad_input("lattice JSON: displacement {} is not [i,j,k,dx,dy,dz]", r);
      int idx[3];
      for (std::size_t a = 0; a < 3; ++a) {
        if (!e[a].is_number_integer()) throw bad_input("lattice JSON: displacement {} has a non-integer index", r);
        const long long v = e[a].get<long long>();
        if (v < 0 || v >= l.dims[a]) throw bad_input("lattice JSON: displacement {} index {} is outside 0..{}", r, v, l.dims[a] - 1);
        idx[a] = static_cast<int>(v);
      }
      Eigen::Vector3d v;
      for (std::size_t a = 0; a < 3; ++a) {
        if (!e[3 + a].is_number()) throw bad_input("lattice JSON: displacement {} is not numeric", r);
        v[static_cast<Eigen::Index>(a)] = e[3 + a].get<double>();
      }
      if (!v.allFinite()) throw bad_input("lattice JSON: displacement {} is not finite", r);
      l.displacement[l.index(idx[0], idx[1], idx[2])] = v;
    }
  } else if (j.contains("points")) {
    const json& p = j["points"];
    if (!p.is_array() || p.size() != l.size())
      throw bad_input("lattice JSON: points must list all {} control points", l.size());
    for (int k = 0; k < l.dims[2]; ++k)
      for (int jj = 0; jj < l.dims[1]; ++jj)
        for (int i = 0; i < l.dims[0]; ++i) {
          const std::size_t n = l.index(i, jj, k);
          l.displacement[n] = vec3(p[n], "a point") - l.rest_point(i, jj, k);
        }
  }
  l.validate();
  return l;
}

std::string encode_lattice_json(const Lattice& l) {
  json j;
  j["origin"] = {l.origin[0], l.origin[1], l.origin[2]};
  j["axes"] = json::array();
  for (const auto& a : l.axes) j["axes"].push_back({a[0], a[1], a[2]});
  j["dims"] = {l.dims[0], l.dims[1], l.dims[2]};
  if (l.basis[0] == l.basis[1] && l.basis[1] == l.basis[2]) j["basis"] = basis_name(l.basis[0]);
  else j["basis"] = {basis_name(l.basis[0]), basis_name(l.basis[1]), basis_name(l.basis[2])};
  j["displacements"] = json::array();
  for (int k = 0; k < l.dims[2]; ++k)
    for (int jj = 0; jj < l.dims[1]; ++jj)
      for (int i = 0; i < l.dims[0]; ++i) {
        if (l.displacement.empty()) continue;
        const Eigen::Vector3d& d = l.displacement[l.index(i, jj, k)];
        if (d.isZero(0)) continue;
        j["displacements"].push_back({i, jj, k, d[0], d[1], d[2]});
      }
  return j.dump(1) + "\n";
}

}  // namespace fest::ffd
