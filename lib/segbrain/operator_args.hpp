#pragma once
// Argument helpers shared by the operator registrations in workspace_*.cpp.

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "segbrain/engine.hpp"
#include "segbrain/grid.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain::args {

inline Object mask_object(Mask m) {
  Object o;
  o.is_mask = true;
  o.mask = std::move(m);
  return o;
}
inline Object image_object(Image i) {
  Object o;
  o.image = std::move(i);
  return o;
}
// slice(axial) -> true (in-plane), volume -> false.
inline bool in_plane_scope(const Term& t) {
  Term d = deref(t);
  if (d->kind == Kind::atom && d->name == "volume") return false;
  if (d->kind == Kind::compound && d->name == "slice" && d->args.size() == 1 && is_atom(d->args[0], "axial")) return true;
  throw bad_input("scope must be volume or slice(axial), got {}", to_string(d));
}
// A list of n numbers.
inline std::vector<double> numbers(Engine& e, const Term& t, std::size_t n, const char* what) {
  std::vector<Term> items;
  if (!list_items(deref(t), items) || items.size() != n) throw bad_input("expected {}, got {}", what, to_string(deref(t)));
  std::vector<double> v;
  for (const auto& it : items) v.push_back(e.eval(it));
  return v;
}
inline Term number_list(const std::vector<double>& v) {
  std::vector<Term> items;
  for (double x : v) items.push_back(make_real(x));
  return make_list(items);
}
// Canonical-grid position (mm) of a voxel index.
inline std::vector<double> position_mm(const Grid& g, std::size_t i) {
  return {double(i % g.n[0]) * g.spacing[0], double((i / g.n[0]) % g.n[1]) * g.spacing[1],
          double(i / (g.n[0] * g.n[1])) * g.spacing[2]};
}

}  // namespace fest::segbrain::args
