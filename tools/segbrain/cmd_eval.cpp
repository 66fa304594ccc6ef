// segbrain eval: Dice, Jaccard and volume difference of label volumes, object by object.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "segbrain/measures.hpp"
#include "segbrain/morphology.hpp"
#include "volume_files.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

namespace {

Mask select(const Volume& v, const LabelRanges& ranges) {
  Mask m(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (const auto& [lo, hi] : ranges)
      if (v.voxels[i] >= lo && v.voxels[i] <= hi) {
        m[i] = 1;
        break;
      }
  return m;
}

bool same_grid(const Volume& a, const Volume& b) {
  if (a.dims != b.dims) return false;
  for (int i = 0; i < 3; ++i)
    if (std::abs(a.spacing[i] - b.spacing[i]) > 1e-4 || std::abs(a.origin[i] - b.origin[i]) > 1e-3) return false;
  for (int i = 0; i < 9; ++i)
    if (std::abs(a.direction[i] - b.direction[i]) > 1e-5) return false;
  return true;
}

// The reference on the segmentation's grid: each voxel takes the value of the reference
// voxel nearest to its world position (0 outside the reference), so label volumes of
// other voxel sizes, orientations or fields of view compare by anatomy (segbrain(1), eval).
Volume resample_nearest(const Volume& ref, const Volume& grid) {
  // Inverse of world = origin + D diag(s) ijk.
  double m[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[3 * r + c] = ref.direction[3 * r + c] * ref.spacing[c];
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (std::abs(det) < 1e-12) throw bad_input("the reference's voxel axes are degenerate");
  const double inv[9] = {(m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det, (m[1] * m[5] - m[2] * m[4]) / det,
                         (m[5] * m[6] - m[3] * m[8]) / det, (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
                         (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det, (m[0] * m[4] - m[1] * m[3]) / det};
  Volume out = grid;
  out.type = ref.type;
  for (std::size_t k = 0; k < grid.dims[2]; ++k)
    for (std::size_t j = 0; j < grid.dims[1]; ++j)
      for (std::size_t i = 0; i < grid.dims[0]; ++i) {
        auto w = grid.world(double(i), double(j), double(k));
        const double d[3] = {w[0] - ref.origin[0], w[1] - ref.origin[1], w[2] - ref.origin[2]};
        double v = 0;
        long long p[3];
        bool inside = true;
        for (int r = 0; r < 3; ++r) {
          p[r] = std::llround(inv[3 * r] * d[0] + inv[3 * r + 1] * d[1] + inv[3 * r + 2] * d[2]);
          inside = inside && p[r] >= 0 && p[r] < static_cast<long long>(ref.dims[r]);
        }
        if (inside) v = ref.at(std::size_t(p[0]), std::size_t(p[1]), std::size_t(p[2]));
        out.at(i, j, k) = v;
      }
  return out;
}

}  // namespace

int run_eval(const EvalArgs& a) {
  Volume ref = read_volume_input(a.ref, "segbrain");
  Volume seg = read_volume_input(a.seg, "segbrain");
  if (!same_grid(ref, seg)) ref = resample_nearest(ref, seg);
  const ObjectMap& smap = a.map;
  const ObjectMap& rmap = a.ref_map;
  std::string out = "object\tdice\tjaccard\tvolume_seg_ml\tvolume_ref_ml\tvolume_diff_pct\n";
  const double ml = seg.spacing[0] * seg.spacing[1] * seg.spacing[2] / 1000.0;
  for (const auto& [name, ranges] : smap) {
    auto it = std::find_if(rmap.begin(), rmap.end(), [&](const auto& r) { return r.first == name; });
    if (it == rmap.end()) throw usage_error("--ref-map has no object '{}'", name);
    Mask s = select(seg, ranges), r = select(ref, it->second);
    double d = dice(s, r);
    double vs = double(count(s)) * ml, vr = double(count(r)) * ml;
    out += fmt::format("{}\t{:.4f}\t{:.4f}\t{:.2f}\t{:.2f}\t{:.2f}\n", name, d, d / (2 - d), vs, vr,
                       vr > 0 ? 100 * (vs - vr) / vr : 0.0);
  }
  write_output("-", out);
  return 0;
}

}  // namespace fest::segbrain_tool
