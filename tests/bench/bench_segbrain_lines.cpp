// Throughputs of segbrain's second-order and line-tracking operators on the 1 mm
// synthetic head (single thread, median of 5 runs, one JSON line each): Laplacian of
// Gaussian (sigma 2 mm, in-plane and in the volume), Marr-Hildreth zero crossings,
// region division of the axial slices, Hessian tubularity in the orbit-chiasm box and
// the two optic-nerve paths. Never fails on timing.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "segbrain/edges.hpp"
#include "segbrain/phantom.hpp"
#include "segbrain/regions.hpp"
#include "segbrain/tracking.hpp"

using namespace fest::segbrain;

namespace {

double median_seconds(const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < 5; ++i) {
    auto a = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[2];
}

}  // namespace

int main() {
  PhantomOptions o;  // 160 x 192 x 160 at 1 mm
  Phantom p = make_phantom(o);
  const Grid& g = p.grid;
  std::size_t sink = 0;
  auto report = [&](const char* name, double voxels, double s) {
    std::printf("{\"bench\":\"segbrain_lines\",\"op\":\"%s\",\"mvox\":%.3f,\"seconds\":%.4f,\"mvox_per_s\":%.1f}\n", name,
                voxels / 1e6, s, voxels / 1e6 / s);
  };
  const double n = double(g.size());
  report("log_sigma2mm_slice", n, median_seconds([&] { sink += laplacian_of_gaussian(g, p.t1, 2.0, true)[7] > 0; }));
  report("log_sigma2mm_volume", n, median_seconds([&] { sink += laplacian_of_gaussian(g, p.t1, 2.0, false)[7] > 0; }));
  Image log = laplacian_of_gaussian(g, p.t1, 2.0, true);
  report("zero_crossings_slice", n, median_seconds([&] { sink += zero_crossings(g, log, 0.02, true)[7]; }));
  Mask edges = zero_crossings(g, log, 0.02, true);
  Mask head(g.size());
  for (std::size_t i = 0; i < head.size(); ++i) head[i] = p.truth[i] != 0;
  report("regions_slice", n, median_seconds([&] { sink += divide_into_regions(g, edges, head, p.t1, Mask(), true).table.size(); }));

  // The optic nerves as the knowledge base tracks them (true eye positions).
  auto canon = [&](const std::array<double, 3>& q) {
    std::array<double, 3> c;
    for (int a = 0; a < 3; ++a) c[a] = q[a] + 0.5 * double(g.n[a] - 1) * g.spacing[a];
    return c;
  };
  const auto e0 = canon(phantom_eye_centres()[0]), e1 = canon(phantom_eye_centres()[1]);
  const double mid = 0.5 * (e0[0] + e1[0]);
  Mask roi(g.size()), zone(g.size());
  std::array<Mask, 2> pole{Mask(g.size()), Mask(g.size())};
  std::size_t roi_voxels = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double x = double(i % g.n[0]), y = double((i / g.n[0]) % g.n[1]), z = double(i / (g.n[0] * g.n[1]));
    roi[i] = x >= e0[0] - 10 && x <= e1[0] + 10 && y >= e0[1] - 75 && y <= e0[1] && z >= e0[2] - 15 && z <= e0[2] + 35;
    roi_voxels += roi[i];
    zone[i] = std::abs(x - mid) <= 2 && y >= e0[1] - 65 && y <= e0[1] - 35 && z >= e0[2] && z <= e0[2] + 25;
    for (int s = 0; s < 2; ++s) {
      const auto c = canon(phantom_nerves()[std::size_t(s)].from);
      pole[std::size_t(s)][i] = (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]) <= 4;
    }
  }
  report("vesselness_sigma1.5mm_roi", double(roi_voxels),
         median_seconds([&] { sink += vesselness(g, p.t1, 1.5, Polarity::any, roi)[7] > 0; }));
  Image v = vesselness(g, p.t1, 1.5, Polarity::any, roi);
  Image cost(g.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    cost[i] = static_cast<float>(1.0 / (0.05 + v[i]) * (p.t1[i] >= 55 && p.t1[i] <= 121 ? 1 : 5));
  report("line_track_two_nerves", double(roi_voxels), median_seconds([&] {
           sink += line_track(g, cost, pole[0], zone, 10).size() + line_track(g, cost, pole[1], zone, 10).size();
         }));
  std::fprintf(stderr, "(%zu)\n", sink);
  return 0;
}
