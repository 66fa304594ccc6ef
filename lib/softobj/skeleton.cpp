#include "softobj/skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"

namespace fest::softobj {

void validate(const Skeleton& s) {
  const int n = static_cast<int>(s.vertices.size());
  if (s.primitive_count() == 0) throw bad_input("empty skeleton: no triangles, segments or points");
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    if (!s.vertices[i].allFinite()) throw bad_input("vertex {} is not finite", i);
  auto check = [&](const char* what, std::size_t i, int idx) {
    if (idx < 0 || idx >= n) throw bad_input("{} {} references vertex {} (only {} vertices)", what, i, idx, n);
  };
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (int k : s.triangles[i]) check("triangle", i, k);
  for (std::size_t i = 0; i < s.segments.size(); ++i)
    for (int k : s.segments[i]) check("segment", i, k);
  for (std::size_t i = 0; i < s.points.size(); ++i) check("point", i, s.points[i]);
  if (!s.charges.empty() && s.charges.size() != s.primitive_count())
    throw bad_input("{} charges for {} primitives", s.charges.size(), s.primitive_count());
  if (!(s.charge > 0) || !std::isfinite(s.charge)) throw bad_input("charge {} is not a positive number", s.charge);
  for (std::size_t i = 0; i < s.charges.size(); ++i)
    if (!(s.charges[i] > 0) || !std::isfinite(s.charges[i]))
      throw bad_input("charge {} ({}) is not a positive number", i, s.charges[i]);
  if (!std::isfinite(s.iso) || s.iso < 0) throw bad_input("iso {} is not a positive number", s.iso);
}

CompiledSkeleton compile_terms(const Skeleton& s) {
  validate(s);
  CompiledSkeleton c;
  const auto& V = s.vertices;
  // Triangles of nonzero area form the complex; degenerate ones become their longest edge.
  std::map<std::pair<int, int>, std::pair<int, double>> edges;  // edge -> (k_e, sum of charges)
  std::map<int, std::pair<int, double>> tri_at_vertex;         // vertex -> (#triangles, sum of charges)
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const auto& t = s.triangles[i];
    const double p = s.charge_of(i);
    const double scale = std::max({(V[t[1]] - V[t[0]]).squaredNorm(), (V[t[2]] - V[t[1]]).squaredNorm(),
                                   (V[t[0]] - V[t[2]]).squaredNorm()});
    const double area2 = (V[t[1]] - V[t[0]]).cross(V[t[2]] - V[t[0]]).squaredNorm();
    if (area2 <= 1e-24 * scale * scale) {
      c.degenerate_triangles.push_back(static_cast<int>(i));
      int a = t[0], b = t[1];
      for (int k = 0; k < 3; ++k)
        if ((V[t[(k + 1) % 3]] - V[t[k]]).squaredNorm() > (V[b] - V[a]).squaredNorm()) a = t[k], b = t[(k + 1) % 3];
      c.terms.push_back({Term::segment, {V[a], V[b], V[b]}, p});
      continue;
    }
    c.terms.push_back({Term::triangle, {V[t[0]], V[t[1]], V[t[2]]}, p});
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      auto& e = edges[{a, b}];
      e.first += 1;
      e.second += p;
      auto& v = tri_at_vertex[t[k]];
      v.first += 1;
      v.second += p;
    }
  }
  // Inclusion-exclusion (docs/softobj.md §1): shared edges subtract (k_e - 1) p_e,
  // vertices add w_v p_v.
  std::map<int, int> shared_at_vertex;
  for (const auto& [e, kp] : edges) {
    if (kp.first < 2) continue;
    ++c.shared_edges;
    const double pe = kp.second / kp.first;
    c.terms.push_back({Term::segment, {V[e.first], V[e.second], V[e.second]}, -(kp.first - 1) * pe});
    shared_at_vertex[e.first] += kp.first - 1;
    shared_at_vertex[e.second] += kp.first - 1;
  }
  for (const auto& [v, np] : tri_at_vertex) {
    const int w = 1 - np.first + shared_at_vertex[v];
    if (w != 0) c.terms.push_back({Term::point, {V[v], V[v], V[v]}, w * np.second / np.first});
  }
  c.euler_characteristic = static_cast<int>(tri_at_vertex.size()) - static_cast<int>(edges.size()) +
                           static_cast<int>(s.triangles.size() - c.degenerate_triangles.size());
  for (std::size_t i = 0; i < s.segments.size(); ++i)
    c.terms.push_back({Term::segment, {V[s.segments[i][0]], V[s.segments[i][1]], V[s.segments[i][1]]},
                       s.charge_of(s.triangles.size() + i)});
  for (std::size_t i = 0; i < s.points.size(); ++i)
    c.terms.push_back({Term::point, {V[s.points[i]], V[s.points[i]], V[s.points[i]]},
                       s.charge_of(s.triangles.size() + s.segments.size() + i)});
  for (const Term& t : c.terms) c.total_charge += t.p;
  // Centre and bounding radius of the used vertices.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const Term& t : c.terms)
    for (const auto& v : t.v) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  c.centre = 0.5 * (lo + hi);
  for (const Term& t : c.terms)
    for (const auto& v : t.v) c.bound_radius = std::max(c.bound_radius, (v - c.centre).norm());
  return c;
}

}  // namespace fest::softobj
