#pragma once
// A soft-object skeleton (docs/softobj.md §1): vertices, triangles, free segments and free
// points, each primitive carrying a positive charge. The derived terms of the
// inclusion-exclusion field (shared edges with multiplicity, vertex weights w_v) are
// computed by compile_terms().

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::softobj {

struct Skeleton {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 2>> segments;
  std::vector<int> points;
  // Charges: one per triangle, then per segment, then per point; empty = all `charge`.
  std::vector<double> charges;
  double charge = 1.0;
  double iso = 0;  // 0 = not given
  std::string units;

  std::size_t primitive_count() const { return triangles.size() + segments.size() + points.size(); }
  double charge_of(std::size_t primitive) const { return charges.empty() ? charge : charges[primitive]; }
};

// One term of the field sum: p / distance(r, primitive), signed weight folded into p.
struct Term {
  enum Kind { point, segment, triangle } kind;
  std::array<Eigen::Vector3d, 3> v;  // point: v[0]; segment: v[0..1]; triangle: v[0..2]
  double p;                          // weight x charge (negative for shared edges)
};

struct CompiledSkeleton {
  std::vector<Term> terms;
  double total_charge = 0;  // Q = p chi for a uniform charge (docs/softobj.md §1)
  int shared_edges = 0;
  int euler_characteristic = 0;  // of the triangle complex (V_used - E + T)
  std::vector<int> degenerate_triangles;  // zero area: treated as their longest edge
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double bound_radius = 0;
};

// Checks indices, finiteness and charges; throws fest::Error(bad_input) naming the
// offending primitive ("triangle 7 references vertex 12 (only 10 vertices)").
void validate(const Skeleton& s);

// The inclusion-exclusion terms of docs/softobj.md §1: +p per triangle, -p per edge
// shared by k >= 2 triangles (weight k - 1), w_v p per triangle vertex with
// w_v = 1 - #triangles(v) + sum over shared edges at v of (k_e - 1); plus free segments
// and points. Edge and vertex charges are the mean charge of the incident triangles.
CompiledSkeleton compile_terms(const Skeleton& s);

}  // namespace fest::softobj
