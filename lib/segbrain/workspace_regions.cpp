// Foreign predicates of the chapter's edge-based find_brain: divide the image into
// regions along Marr-Hildreth edges, choose the starting region, aggregate the brain.
#include <memory>

#include "segbrain/operator_args.hpp"
#include "segbrain/regions.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain {

void Workspace::register_region_operators(Engine& engine) {
  using namespace args;
  engine.register_foreign("regions", 6, "+Img, +Edges, +Head, +SkinMM, +Scope, -Regions",
      "components of Head minus Edges (4-conn per axial slice, 6 in the volume) with mean intensity, "
      "skin contact (a voxel within SkinMM of the head outline) and adjacency across edge voxels",
      [this](Engine& e, const std::vector<Term>& a) {
        const std::string head = name_of(a[2]);
        const double skin_mm = e.eval(a[3]);
        const std::vector<double>& depth = depth_of(head);
        const Mask& hm = mask(head);
        Mask skin(hm.size());
        for (std::size_t i = 0; i < skin.size(); ++i) skin[i] = hm[i] && depth[i] <= skin_mm;
        auto r = std::make_shared<Regions>(
            divide_into_regions(grid_, mask(name_of(a[1])), hm, image(name_of(a[0])), skin, in_plane_scope(a[4])));
        Object o = mask_object(Mask(grid_.size(), 0));
        for (std::size_t i = 0; i < o.mask.size(); ++i) o.mask[i] = r->label[i] != 0;
        e.measure() = {{"regions", double(r->table.size() - 1)}};
        o.regions = std::move(r);
        return create(e, a[5], std::move(o));
      });
  auto regions_of = [this](const std::string& name) -> const Regions& {
    const Object& o = get(name);
    if (!o.regions) throw bad_input("'{}' is not a region division (from regions/6)", name);
    return *o.regions;
  };
  engine.register_foreign("brain_starting_region", 6, "+Regions, +Head, +RefFraction, +Lo, +Hi, -Start",
      "in the axial slice at RefFraction of the head's S-extent, the largest region with mean in [Lo, Hi], "
      "no skin contact and centroid in the central half of the head; fails if none",
      [this, regions_of](Engine& e, const std::vector<Term>& a) {
        const Regions& r = regions_of(name_of(a[0]));
        const std::uint32_t id =
            brain_starting_region(grid_, r, mask(name_of(a[1])), e.eval(a[3]), e.eval(a[4]), e.eval(a[2]));
        if (!id) return false;
        Mask m(grid_.size(), 0);
        for (std::size_t i = 0; i < m.size(); ++i) m[i] = r.label[i] == id;
        e.measure() = {{"start_area_mm2", double(r.table[id].voxels) * grid_.spacing[0] * grid_.spacing[1]},
                       {"start_mean", r.table[id].mean}};
        return create(e, a[5], mask_object(std::move(m)));
      });
  engine.register_foreign("aggregate_brain_regions", 7, "+Regions, +Start, +Lo, +Hi, +MinOverlap, +MinAreaMM2, -Mask",
      "breadth first over adjacent regions with mean in [Lo, Hi] and no skin contact, then slice by slice up "
      "and down (seeds overlap the previous slice by >= MinOverlap of their area) until the area < MinAreaMM2",
      [this, regions_of](Engine& e, const std::vector<Term>& a) {
        const Regions& r = regions_of(name_of(a[0]));
        const Mask& start = mask(name_of(a[1]));
        std::uint32_t id = 0;
        for (std::size_t i = 0; i < start.size() && !id; ++i)
          if (start[i]) id = r.label[i];
        if (!id) throw bad_input("aggregate_brain_regions: the start mask lies in no region");
        Mask m = aggregate_brain_regions(grid_, r, id, e.eval(a[2]), e.eval(a[3]), e.eval(a[4]), e.eval(a[5]));
        return create(e, a[6], mask_object(std::move(m)));
      });
}

}  // namespace fest::segbrain
