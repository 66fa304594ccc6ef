#pragma once
// The hemicube of Cohen & Greenberg 1985 (docs/radiosity.md §3): a unit hemicube at a
// point with a normal, its top face H x H pixels and four half faces H x H/2, delta form
// factors
//
//   top:  dF = dA / (pi (x^2 + y^2 + 1)^2)        side: dF = z dA / (pi (y^2 + z^2 + 1)^2)
//
// at pixel centres, normalised so that the whole table sums to exactly 1 (the raw sum is
// kept: it must lie within 1e-3 of 1). Every polygon is clipped to each face's frustum
// and rasterised into a float 1/z buffer with an item buffer; the nearest item wins, ties
// go to the lower item index. F_{x->item} is the sum of dF over the pixels showing it.
//
// The work is six equal tasks (the top face in two halves and the four side faces), run
// on up to `threads` threads; each task sums into its own row and the rows are added in
// task order, so the result does not depend on the thread count.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "radiosity/model.hpp"

namespace fest::radiosity {

class Hemicube {
 public:
  explicit Hemicube(int resolution);  // H, even, >= 2

  int resolution() const { return res_; }
  double raw_sum() const { return raw_sum_; }  // sum of the unnormalised delta form factors

  // ff[k] = F_{dx->items[k]} for a differential area at `centre` facing `normal`.
  // Items with draw[k] == 0 are ignored (the shooter's own elements); items facing away
  // from the centre occlude but receive nothing. `near` is a length below which depths
  // are clipped (a tiny fraction of the scene size).
  // With `coverage` and `visible`, also per item the sum of dF over every pixel it
  // covers whatever lies in front of it, and over the pixels where it is visible
  // counting depth ties (a pixel centre on the edge two neighbours share shows both):
  // visible / coverage is the item's visible fraction (the hybrid engine).
  void project(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, const std::vector<const Polygon*>& items,
               const std::vector<std::uint8_t>& draw, double near, int threads, std::vector<double>& ff,
               std::vector<double>* coverage = nullptr, std::vector<double>* visible = nullptr);

 private:
  struct Task {
    std::vector<float> dff;  // normalised delta form factors, H x H/2
    std::vector<float> depth;
    std::vector<std::int32_t> id;
    std::vector<double> row;
    std::vector<double> cover;
    std::vector<std::int32_t> seen;  // last item counted in cover, per pixel (fan triangles share edges)
    std::vector<std::int32_t> tie;   // an item at the same depth as the winner, or -1
    std::vector<double> vis;
  };
  void run_task(int t, const std::vector<const Polygon*>& items, double near, bool coverage);

  int res_;
  double raw_sum_ = 0;
  Task tasks_[6];
  // Corner coordinates in the local frame (u, v, n) of the current projection.
  std::vector<Eigen::Vector3d> local_;
  std::vector<std::int32_t> item_id_;  // id drawn for each item (-1: occluder only, -2: culled)
};

// A right-handed tangent frame (u, v) for a unit normal n (deterministic).
void tangent_frame(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v);

}  // namespace fest::radiosity
