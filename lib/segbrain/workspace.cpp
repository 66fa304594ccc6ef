// Workspace objects and the foreign predicates that operate on them.
#include "segbrain/workspace.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "segbrain/filters.hpp"
#include "segbrain/lateral_extent.hpp"
#include "segbrain/measures.hpp"
#include "segbrain/morphology.hpp"
#include "segbrain/shape.hpp"

namespace fest::segbrain {

const Object& Workspace::get(const std::string& name) const {
  auto it = objects_.find(name);
  if (it == objects_.end()) throw bad_input("no object named '{}' in the workspace", name);
  return *it->second;
}
const Image& Workspace::image(const std::string& name) const {
  const Object& o = get(name);
  if (o.is_mask) throw bad_input("object '{}' is a mask, an image is needed", name);
  return o.image;
}
const Mask& Workspace::mask(const std::string& name) const {
  const Object& o = get(name);
  if (!o.is_mask) throw bad_input("object '{}' is an image, a mask is needed", name);
  return o.mask;
}
void Workspace::put_root(const std::string& name, Object obj) {
  objects_[name] = std::make_shared<const Object>(std::move(obj));
}

std::string Workspace::name_of(const Term& t) const {
  Term d = deref(t);
  if (d->kind != Kind::atom) throw bad_input("expected an object name, got {}", to_string(d));
  return d->name;
}

const std::vector<double>& Workspace::depth_of(const std::string& name) {
  mask(name);  // the right message when it is missing or not a mask
  const auto& obj = objects_.at(name);
  auto& slot = depth_cache_[name];
  // A weak reference: a released object (and a new one under the same name) misses.
  if (slot.first.lock() != obj) slot = {obj, std::make_shared<const std::vector<double>>(depth(grid_, obj->mask))};
  return *slot.second;
}

bool Workspace::create(Engine& e, const Term& out, Object obj) {
  Term d = deref(out);
  std::string name;
  if (d->kind == Kind::var) {
    name = fmt::format("_obj{}", ++fresh_);
    e.unify(d, make_atom(name));
  } else if (d->kind == Kind::atom) {
    name = d->name;
    if (objects_.count(name)) throw bad_input("object '{}' exists already", name);
  } else {
    throw bad_input("output must be an unbound variable or an atom, got {}", to_string(d));
  }
  objects_[name] = std::make_shared<const Object>(std::move(obj));
  e.on_backtrack([this, name] { objects_.erase(name); });
  return true;
}

namespace {

Object mask_object(Mask m) {
  Object o;
  o.is_mask = true;
  o.mask = std::move(m);
  return o;
}
Object image_object(Image i) {
  Object o;
  o.image = std::move(i);
  return o;
}
double num(Engine& e, const Term& t) { return e.eval(t); }
int conn_of(Engine& e, const Term& t) {
  int c = static_cast<int>(num(e, t));
  if (c != 4 && c != 8 && c != 6 && c != 18 && c != 26) throw bad_input("connectivity {} (4, 8, 6, 18 or 26)", c);
  return c;
}
int axis_of(const Term& t) {
  for (int a = 0; a < 3; ++a)
    if (is_atom(t, a == 0 ? "r" : a == 1 ? "a" : "s")) return a;
  throw bad_input("axis must be r, a or s, got {}", to_string(deref(t)));
}
Term number_list(const double* v, std::size_t n) {
  std::vector<Term> items;
  for (std::size_t i = 0; i < n; ++i) items.push_back(make_real(v[i]));
  return make_list(items);
}
Point point_of(Engine& e, const Term& t) {
  std::vector<Term> items;
  if (!list_items(deref(t), items) || items.size() != 3) throw bad_input("expected a point [R, A, S], got {}", to_string(deref(t)));
  return {e.eval(items[0]), e.eval(items[1]), e.eval(items[2])};
}

// volume -> -1; slice(axial | coronal | sagittal) -> the axis across which the sections lie.
int slice_scope(const Term& t) {
  Term d = deref(t);
  if (d->kind == Kind::atom && d->name == "volume") return -1;
  if (d->kind == Kind::compound && d->name == "slice" && d->args.size() == 1) {
    if (is_atom(d->args[0], "axial")) return 2;
    if (is_atom(d->args[0], "coronal")) return 1;
    if (is_atom(d->args[0], "sagittal")) return 0;
  }
  throw bad_input("scope must be volume or slice(axial | coronal | sagittal), got {}", to_string(d));
}

}  // namespace

void Workspace::register_operators(Engine& engine) {
  const Grid& g = grid_;
  auto ml = [&g](const Mask& m) { return static_cast<double>(count(m)) * g.voxel_ml(); };

  // --- segmentation / feature operators ---
  engine.register_foreign("robust_range", 4, "+Img, +Mask|all, -P2, -P98", "2nd and 98th intensity percentiles",
      [this](Engine& e, const std::vector<Term>& a) {
        const Image& img = image(name_of(a[0]));
        Mask empty;
        const Mask& m = is_atom(a[1], "all") ? empty : mask(name_of(a[1]));
        double p2 = percentile(img, m, 2), p98 = percentile(img, m, 98);
        if (std::isnan(p2)) return false;
        return e.unify(a[2], make_real(p2)) && e.unify(a[3], make_real(p98));
      });
  engine.register_foreign("smooth", 3, "+Img, +SigmaMM, -Out", "separable Gaussian, radius ceil(3 sigma / spacing)",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[2], image_object(gaussian_smooth(grid_, image(name_of(a[0])), num(e, a[1]))));
      });
  engine.register_foreign("threshold", 4, "+Img, +Lo, +Hi, -Mask", "Lo <= I <= Hi (inf allowed)",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[3], mask_object(threshold(image(name_of(a[0])), num(e, a[1]), num(e, a[2]))));
      });
  engine.register_foreign("otsu", 3, "+Img, +Mask|all, -T", "Otsu threshold on a 256-bin histogram",
      [this](Engine& e, const std::vector<Term>& a) {
        Mask empty;
        const Mask& m = is_atom(a[1], "all") ? empty : mask(name_of(a[1]));
        return e.unify(a[2], make_real(otsu_threshold(image(name_of(a[0])), m)));
      });
  engine.register_foreign("deep_intensity", 4, "+Img, +Mask, +Frac, -Ref",
      "median of the upper half of intensities among the deepest Frac of the mask",
      [this](Engine& e, const std::vector<Term>& a) {
        std::string in = name_of(a[0]), mn = name_of(a[1]);
        image(in);
        mask(mn);
        const auto& io = objects_.at(in);
        const auto& mo = objects_.at(mn);
        const double frac = num(e, a[2]);
        double w = std::nan("");
        bool hit = false;
        for (const auto& m : deep_memo_)
          if (m.image.lock() == io && m.mask.lock() == mo && m.frac == frac) {
            w = m.value;
            hit = true;
            ++memo_hits_;
          }
        if (!hit) {
          w = deep_intensity(io->image, mo->mask, depth_of(mn), frac);
          deep_memo_.push_back({io, mo, frac, w});
        }
        if (std::isnan(w)) return false;
        e.measure() = {{"deep_intensity", w}};
        return e.unify(a[3], make_real(w));
      });
  engine.register_foreign("region_grow", 7, "+Img, +Seeds, +Lo, +Hi, +Conn, +Within|all, -Mask", "flood fill over Lo <= I <= Hi",
      [this](Engine& e, const std::vector<Term>& a) {
        Mask empty;
        const Mask& within = is_atom(a[5], "all") ? empty : mask(name_of(a[5]));
        return create(e, a[6], mask_object(region_grow(grid_, image(name_of(a[0])), mask(name_of(a[1])), num(e, a[2]),
                                                       num(e, a[3]), conn_of(e, a[4]), within)));
      });
  engine.register_foreign("largest_component", 3, "+Mask, +Conn, -Out", "largest connected component",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[2], mask_object(largest_component(grid_, mask(name_of(a[0])), conn_of(e, a[1]))));
      });
  engine.register_foreign("largest_fraction", 2, "+Mask, -Q", "fraction of the mask in its largest 26-connected component",
      [this](Engine& e, const std::vector<Term>& a) {
        const Mask& m = mask(name_of(a[0]));
        std::size_t n = count(m);
        double q = n ? double(count(largest_component(grid_, m, 26))) / double(n) : 0.0;
        e.measure() = {{"largest_fraction", q}};
        return e.unify(a[1], make_real(q));
      });
  engine.register_foreign("fill_holes", 3, "+Mask, +volume|slice(axial|coronal|sagittal), -Out",
      "fill background not connected to the grid border (in 3-D or section by section)",
      [this](Engine& e, const std::vector<Term>& a) {
        const int axis = slice_scope(a[1]);
        const Mask& m = mask(name_of(a[0]));
        return create(e, a[2], mask_object(axis < 0 ? fill_holes(grid_, m, false) : fill_holes_sections(grid_, m, axis)));
      });
  // --- post-processing: morphology on the exact distance transform ---
  auto morph = [&](const char* name, Mask (*op)(const Grid&, const Mask&, double)) {
    engine.register_foreign(name, 3, "+Mask, +RadiusMM, -Out", "ball morphology via the exact distance transform",
        [this, op](Engine& e, const std::vector<Term>& a) {
          return create(e, a[2], mask_object(op(grid_, mask(name_of(a[0])), num(e, a[1]))));
        });
  };
  morph("erode", &erode);
  morph("dilate", &dilate);
  morph("open", &open);
  morph("close", &close);
  auto logic = [&](const char* name, int which) {
    engine.register_foreign(name, 3, "+A, +B, -Out", "voxel-wise logic", [this, which](Engine& e, const std::vector<Term>& a) {
      const Mask& x = mask(name_of(a[0]));
      const Mask& y = mask(name_of(a[1]));
      Mask m = combine(x, y, which == 0 ? MaskLogic::both : which == 1 ? MaskLogic::either : MaskLogic::first_only);
      return create(e, a[2], mask_object(std::move(m)));
    });
  };
  logic("and", 0);
  logic("or", 1);
  logic("and_not", 2);
  engine.register_foreign("copy", 2, "+Obj, -Out", "duplicate an object under a new name", [this](Engine& e, const std::vector<Term>& a) {
    return create(e, a[1], get(name_of(a[0])));
  });
  engine.register_foreign("exists", 1, "+Name", "the workspace holds the object", [this](Engine&, const std::vector<Term>& a) {
    Term d = deref(a[0]);
    return d->kind == Kind::atom && has(d->name);
  });
  engine.register_foreign("emit", 2, "+Obj, +Label", "mark a mask as an output label (later emits overwrite earlier ones)",
      [this](Engine& e, const std::vector<Term>& a) {
        std::string n = name_of(a[0]);
        mask(n);
        int label = static_cast<int>(num(e, a[1]));
        if (label < 0 || label > 65535) throw bad_input("label {} out of range 0..65535", label);
        emitted_.push_back({n, label});
        e.on_backtrack([this] { emitted_.pop_back(); });
        return true;
      });
  // --- location and shape (canonical-grid mm: index x spacing along R, A, S) ---
  engine.register_foreign("halfspace", 4, "+Axis(r|a|s), +below|above, +ValueMM, -Mask", "voxels below/above a position along one axis",
      [this](Engine& e, const std::vector<Term>& a) {
        bool below = is_atom(a[1], "below");
        if (!below && !is_atom(a[1], "above")) throw bad_input("halfspace: side must be below or above");
        return create(e, a[3], mask_object(halfspace(grid_, axis_of(a[0]), below, num(e, a[2]))));
      });
  engine.register_foreign("components_near", 6, "+Mask, +Conn, +MinMl, +[R,A,S], +MaxDistMM, -Out",
      "components of at least MinMl whose centroid lies within MaxDistMM of the point",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[5], mask_object(components_near(grid_, mask(name_of(a[0])), conn_of(e, a[1]), num(e, a[2]),
                                                           point_of(e, a[3]), num(e, a[4]))));
      });
  engine.register_foreign("components_sized", 5, "+Mask, +Conn, +MinMl, +MaxMl, -Out", "components whose volume lies in [MinMl, MaxMl]",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[4], mask_object(components_sized(grid_, mask(name_of(a[0])), conn_of(e, a[1]), num(e, a[2]), num(e, a[3]))));
      });
  engine.register_foreign("components", 3, "+Mask, +Conn, -N", "number of connected components",
      [this](Engine& e, const std::vector<Term>& a) {
        const double n = double(connected_components(grid_, mask(name_of(a[0])), conn_of(e, a[1])).size.size() - 1);
        e.measure() = {{"components", n}};
        return e.unify(a[2], make_int(static_cast<std::int64_t>(n)));
      });
  engine.register_foreign("symmetric_pair", 7, "+Mask, +Conn, +PlaneRMM, +MinDistMM, +MaxDistMM, -Out, -ScoreMM",
      "the two components mirroring each other best about the plane (fails when no pair fits)",
      [this](Engine& e, const std::vector<Term>& a) {
        double score = 0;
        Mask m = symmetric_pair(grid_, mask(name_of(a[0])), conn_of(e, a[1]), num(e, a[2]), num(e, a[3]), num(e, a[4]), score);
        if (!std::isfinite(score)) return false;
        e.measure() = {{"pair_asymmetry_mm", score}};
        return create(e, a[5], mask_object(std::move(m))) && e.unify(a[6], make_real(score));
      });
  engine.register_foreign("geodesic_dilate", 4, "+Mask, +Within, +RadiusMM, -Out", "growth by at most RadiusMM along paths inside Within",
      [this](Engine& e, const std::vector<Term>& a) {
        return create(e, a[3], mask_object(geodesic_dilate(grid_, mask(name_of(a[0])), mask(name_of(a[1])), num(e, a[2]))));
      });
  engine.register_foreign("lateral_extent", 5, "+Mask, +Within, +PlaneRMM, +MaxHalfWidthMM, -Out",
      "per row along R, each side from the mask's voxel nearest the plane outward while in Within, at most MaxHalfWidthMM; "
      "sides that reach the limit bridged by interpolation between bounded rows (along S, then A), smoothed",
      [this](Engine& e, const std::vector<Term>& a) {
        LateralExtentStats st;
        Mask m = lateral_extent(grid_, mask(name_of(a[0])), mask(name_of(a[1])), num(e, a[2]), num(e, a[3]), &st);
        e.measure() = {{"row_sides", double(st.sides)}, {"open_fraction", st.sides ? double(st.open_sides) / double(st.sides) : 0.0}};
        return create(e, a[4], mask_object(std::move(m)));
      });
  engine.register_foreign("centroid_mm", 2, "+Mask, -[R,A,S]", "mean voxel position (fails for an empty mask)",
      [this](Engine& e, const std::vector<Term>& a) {
        Point c = centroid_mm(grid_, mask(name_of(a[0])));
        if (std::isnan(c[0])) return false;
        return e.unify(a[1], number_list(c.data(), 3));
      });
  engine.register_foreign("bbox_mm", 2, "+Mask, -[R0,R1,A0,A1,S0,S1]", "extreme voxel positions per axis (fails for an empty mask)",
      [this](Engine& e, const std::vector<Term>& a) {
        auto b = bbox_mm(grid_, mask(name_of(a[0])));
        if (std::isnan(b[0])) return false;
        return e.unify(a[1], number_list(b.data(), 6));
      });
  // The scene's first question (docs/segbrain.md §1, field of view): can the volume hold a
  // whole brain at all? Extents in mm, voxel count times spacing along R, A, S.
  engine.register_foreign("field_of_view_mm", 1, "-[ER,EA,ES]", "extent of the volume along R, A, S in mm",
      [this](Engine& e, const std::vector<Term>& a) {
        const double ext[3] = {double(grid_.n[0]) * grid_.spacing[0], double(grid_.n[1]) * grid_.spacing[1], double(grid_.n[2]) * grid_.spacing[2]};
        e.measure() = {{"fov_r_mm", ext[0]}, {"fov_a_mm", ext[1]}, {"fov_s_mm", ext[2]}};
        return e.unify(a[0], number_list(ext, 3));
      });
  engine.register_foreign("midsagittal_plane", 3, "+Img, +Mask, -PlaneRMM",
      "sagittal plane R = c (mm, within 15 mm of the mask's centroid) of greatest mirror correlation",
      [this](Engine& e, const std::vector<Term>& a) {
        double c = midsagittal_r_mm(grid_, image(name_of(a[0])), mask(name_of(a[1])), 15.0);
        if (std::isnan(c)) return false;
        e.measure() = {{"midsagittal_r_mm", c}};
        return e.unify(a[2], make_real(c));
      });
  engine.register_foreign("mirror_dice", 3, "+Mask, +PlaneRMM, -D", "Dice of the mask and its mirror image about the sagittal plane R = PlaneRMM",
      [this](Engine& e, const std::vector<Term>& a) {
        double d = mirror_dice(grid_, mask(name_of(a[0])), num(e, a[1]));
        e.measure() = {{"mirror_dice", d}};
        return e.unify(a[2], make_real(d));
      });

  // --- measurements (verification operators read these) ---
  engine.register_foreign("volume_ml", 2, "+Mask, -V", "volume in ml", [this, ml](Engine& e, const std::vector<Term>& a) {
    double v = ml(mask(name_of(a[0])));
    e.measure() = {{"volume_ml", v}};
    return e.unify(a[1], make_real(v));
  });
  engine.register_foreign("ratio_ml", 3, "+A, +B, -Q", "volume of A over volume of B", [this, ml](Engine& e, const std::vector<Term>& a) {
    double vb = ml(mask(name_of(a[1])));
    double q = vb > 0 ? ml(mask(name_of(a[0]))) / vb : 0.0;
    e.measure() = {{"volume_ratio", q}};
    return e.unify(a[2], make_real(q));
  });
  engine.register_foreign("overlap_ml", 3, "+A, +B, -V", "volume of A and B in ml", [this, ml](Engine& e, const std::vector<Term>& a) {
    const Mask& x = mask(name_of(a[0]));
    const Mask& y = mask(name_of(a[1]));
    Mask m(x.size());
    for (std::size_t i = 0; i < m.size(); ++i) m[i] = x[i] && y[i];
    double v = ml(m);
    e.measure() = {{"overlap_ml", v}};
    return e.unify(a[2], make_real(v));
  });
  engine.register_foreign("skin_contact_fraction", 4, "+Mask, +Head, +DistMM, -F",
      "fraction of the mask within DistMM of the head outline (inside the field of view)",
      [this](Engine& e, const std::vector<Term>& a) {
        double f = skin_contact_fraction(mask(name_of(a[0])), depth_of(name_of(a[1])), num(e, a[2]));
        e.measure() = {{"skin_contact_fraction", f}};
        return e.unify(a[3], make_real(f));
      });
  engine.register_foreign("contour_length_ratio", 4, "+Mask, +Head, +axial, -R",
      "median per-slice ratio of the compactness (perimeter / sqrt(area)) of Mask to that of Head",
      [this](Engine& e, const std::vector<Term>& a) {
        if (!is_atom(a[2], "axial")) throw bad_input("contour_length_ratio: only axial slices are supported");
        double r = contour_length_ratio(grid_, mask(name_of(a[0])), mask(name_of(a[1])));
        e.measure() = {{"contour_length_ratio", r}};
        return e.unify(a[3], make_real(r));
      });
  engine.register_foreign("slice_consistency", 4, "+Mask, +axial, -MaxChange, -MinDice",
      "largest relative area change and smallest Dice between adjacent axial slices (>= 10 cm2)",
      [this](Engine& e, const std::vector<Term>& a) {
        if (!is_atom(a[1], "axial")) throw bad_input("slice_consistency: only axial slices are supported");
        auto [c, d] = slice_consistency(grid_, mask(name_of(a[0])));
        e.measure() = {{"slice_change", c}, {"slice_dice", d}};
        return e.unify(a[2], make_real(c)) && e.unify(a[3], make_real(d));
      });
  engine.register_foreign("depth_shell", 4, "+Mask, +D0, +D1, -Out", "mask voxels whose depth lies in [D0, D1] mm",
      [this](Engine& e, const std::vector<Term>& a) {
        const Mask& m = mask(name_of(a[0]));
        double d0 = num(e, a[1]), d1 = num(e, a[2]);
        const std::vector<double>& d = depth_of(name_of(a[0]));
        Mask out(m.size());
        for (std::size_t i = 0; i < m.size(); ++i) out[i] = m[i] && d[i] >= d0 && d[i] <= d1;
        return create(e, a[3], mask_object(std::move(out)));
      });
  engine.register_foreign("fraction_within", 5, "+Img, +Mask, +Lo, +Hi, -F", "fraction of mask voxels with Lo <= I <= Hi",
      [this](Engine& e, const std::vector<Term>& a) {
        double f = fraction_within(image(name_of(a[0])), mask(name_of(a[1])), num(e, a[2]), num(e, a[3]));
        e.measure() = {{"fraction_within", f}};
        return e.unify(a[4], make_real(f));
      });
  engine.register_foreign("fraction_above", 4, "+Img, +Mask, +T, -F", "fraction of mask voxels with I > T",
      [this](Engine& e, const std::vector<Term>& a) {
        double f = 1.0 - fraction_within(image(name_of(a[0])), mask(name_of(a[1])), -INFINITY, num(e, a[2]));
        if (count(mask(name_of(a[1]))) == 0) f = 0;
        e.measure() = {{"fraction_above", f}};
        return e.unify(a[3], make_real(f));
      });
  register_edge_operators(engine);
  register_tracking_operators(engine);
  register_region_operators(engine);
  register_tissue_operators(engine);
}

std::vector<std::uint16_t> assemble_labels(const Workspace& ws) {
  std::vector<std::uint16_t> out(ws.grid().size(), 0);
  for (const auto& em : ws.emitted()) {
    const Mask& m = ws.mask(em.object);
    for (std::size_t i = 0; i < out.size(); ++i)
      if (m[i]) out[i] = static_cast<std::uint16_t>(em.label);
  }
  return out;
}

}  // namespace fest::segbrain
