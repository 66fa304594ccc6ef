// Exact extraction: docs/isosurf.md "Exact mode" and "Min-max octree".
#include "isosurface/marching_cubes.hpp"

#include <algorithm>
#include <numeric>

#include "core/parallel_for.hpp"

namespace fest::isosurface {
namespace {

using volume_pyramid::MinMaxPyramid;
using volume_pyramid::ScalarGrid;

constexpr std::size_t kBlock = 8;  // cells per block side = 2^(pyramid finest level)
constexpr std::size_t kSlabsPerJob = kBlock;
constexpr std::uint8_t kLowerFaces = 0x15;  // faces 0, 2, 4: the sides at x, y, z = 0
constexpr std::uint32_t kCentroidMark = 0x80000000u;

struct Layer {
  std::vector<std::uint32_t> edge[3];  // vertex id of the x/y/z edge leaving each sample
};

class Extractor {
 public:
  Extractor(const ScalarGrid& g, float iso, const ExtractOptions& o, const MinMaxPyramid* p)
      : g_(g), iso_(iso), opt_(o), pyr_(p), n_{g.dims[0], g.dims[1], g.dims[2]} {
    for (int a = 0; a < 3; ++a) bn_[a] = (n_[a] - 1 + kBlock - 1) / kBlock;
  }

  Surface run(ExtractStats* stats) {
    if (stats) *stats = {};
    const std::size_t rows = n_[1] * n_[2];
    std::vector<std::uint32_t> row_count(rows);
    parallel_for(n_[2], opt_.threads, [&](std::size_t k) {
      for (std::size_t j = 0; j < n_[1]; ++j) row_count[j + n_[1] * k] = count_row(j, k);
    });
    row_base_.resize(rows);
    std::exclusive_scan(row_count.begin(), row_count.end(), row_base_.begin(), std::size_t{0});
    const std::size_t vertices = rows ? row_base_.back() + row_count.back() : 0;
    Surface s;
    s.xyz.resize(3 * vertices);
    xyz_ = s.xyz.data();
    const std::size_t slabs = n_[2] - 1, jobs = (slabs + kSlabsPerJob - 1) / kSlabsPerJob;
    std::vector<std::vector<std::array<std::uint32_t, 3>>> tris(jobs);
    std::vector<ExtractStats> job_stats(jobs);
    std::vector<std::vector<float>> centroids(jobs);
    ProgressCounter jobs_done(opt_.progress, jobs);
    parallel_for(jobs, opt_.threads, [&](std::size_t job) {
      const std::size_t k0 = job * kSlabsPerJob, k1 = std::min(k0 + kSlabsPerJob, slabs);
      Layer lower, upper;
      for (auto* L : {&lower, &upper})
        for (auto& e : L->edge) e.resize(n_[0] * n_[1]);
      fill_layer(k0, lower, true);
      for (std::size_t k = k0; k < k1; ++k) {
        fill_layer(k + 1, upper, k + 1 < k1 || k + 1 == n_[2] - 1);
        cells_of_slab(k, lower, upper, tris[job], centroids[job], job_stats[job]);
        std::swap(lower, upper);
      }
      jobs_done.step();
    });
    jobs_done.finish();
    std::size_t total = 0;
    for (const auto& t : tris) total += t.size();
    s.triangles.reserve(total);
    for (std::size_t job = 0; job < jobs; ++job) {
      const auto first = static_cast<std::uint32_t>(s.vertices());
      for (auto t : tris[job]) {
        for (auto& v : t)
          if (v & kCentroidMark) v = first + (v & ~kCentroidMark);
        s.triangles.push_back(t);
      }
      s.xyz.insert(s.xyz.end(), centroids[job].begin(), centroids[job].end());
      if (stats) stats->centroid_vertices += centroids[job].size() / 3;
    }
    if (g_.determinant() < 0)  // a mirroring index->world map flips every orientation back
      for (auto& t : s.triangles) std::swap(t[1], t[2]);
    if (stats) {
      const std::size_t c = stats->centroid_vertices;
      *stats = {};
      stats->centroid_vertices = c;
      for (const auto& js : job_stats) {
        stats->cells_visited += js.cells_visited;
        stats->blocks_active += js.blocks_active;
      }
      stats->blocks_total = bn_[0] * bn_[1] * bn_[2];
    }
    return s;
  }

 private:
  bool block_active(std::size_t bi, std::size_t bj, std::size_t bk) const {
    return !pyr_ || pyr_->active(3, bi, bj, bk, iso_);
  }
  // The block whose closed region holds every edge leaving sample index s on an axis.
  std::size_t block_of(std::size_t s, int axis) const { return std::min(s / kBlock, bn_[axis] - 1); }

  // Visits the crossed edges leaving the samples of row (j, k) in key order.
  template <typename Visit>
  void for_row_crossings(std::size_t j, std::size_t k, Visit&& visit) const {
    const float* v = &g_.values[g_.index(0, j, k)];
    const float* vy = j + 1 < n_[1] ? v + n_[0] : nullptr;
    const float* vz = k + 1 < n_[2] ? v + n_[0] * n_[1] : nullptr;
    const std::size_t bj = block_of(j, 1), bk = block_of(k, 2);
    for (std::size_t i0 = 0; i0 < n_[0]; i0 += kBlock) {
      if (!block_active(block_of(i0, 0), bj, bk)) continue;
      const std::size_t i1 = std::min(i0 + kBlock, n_[0]);
      for (std::size_t i = i0; i < i1; ++i) {
        const bool in = v[i] >= iso_;
        if (i + 1 < n_[0] && (v[i + 1] >= iso_) != in) visit(i, 0, v[i], v[i + 1]);
        if (vy && (vy[i] >= iso_) != in) visit(i, 1, v[i], vy[i]);
        if (vz && (vz[i] >= iso_) != in) visit(i, 2, v[i], vz[i]);
      }
    }
  }

  std::uint32_t count_row(std::size_t j, std::size_t k) const {
    std::uint32_t c = 0;
    for_row_crossings(j, k, [&](std::size_t, int, float, float) { ++c; });
    return c;
  }

  std::array<double, 3> crossing(std::size_t i, std::size_t j, std::size_t k, int axis, float fa, float fb) const {
    const double t = (static_cast<double>(iso_) - fa) / (static_cast<double>(fb) - fa);
    double p[3] = {double(i), double(j), double(k)};
    p[axis] += t;
    return g_.world(p[0], p[1], p[2]);
  }

  void fill_layer(std::size_t k, Layer& L, bool write_positions) {
    for (std::size_t j = 0; j < n_[1]; ++j) {
      std::uint32_t id = static_cast<std::uint32_t>(row_base_[j + n_[1] * k]);
      for_row_crossings(j, k, [&](std::size_t i, int axis, float fa, float fb) {
        L.edge[axis][i + n_[0] * j] = id;
        if (write_positions) {
          const auto p = crossing(i, j, k, axis, fa, fb);
          for (int c = 0; c < 3; ++c) xyz_[3 * std::size_t{id} + c] = static_cast<float>(p[c]);
        }
        ++id;
      });
    }
  }

  void cells_of_slab(std::size_t k, const Layer& lo, const Layer& hi, std::vector<std::array<std::uint32_t, 3>>& out,
                     std::vector<float>& centroids, ExtractStats& st) const {
    const std::size_t bk = k / kBlock, sx = 1, sy = n_[0], sz = n_[0] * n_[1];
    const std::size_t off[8] = {0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
    for (std::size_t bj = 0; bj < bn_[1]; ++bj)
      for (std::size_t bi = 0; bi < bn_[0]; ++bi) {
        if (!block_active(bi, bj, bk)) continue;
        if (k % kBlock == 0) ++st.blocks_active;
        const std::size_t j1 = std::min((bj + 1) * kBlock, n_[1] - 1), i1 = std::min((bi + 1) * kBlock, n_[0] - 1);
        for (std::size_t j = bj * kBlock; j < j1; ++j)
          for (std::size_t i = bi * kBlock; i < i1; ++i) {
            const float* base = &g_.values[g_.index(i, j, k)];
            float val[8];
            int cube = 0;
            for (int c = 0; c < 8; ++c) {
              val[c] = base[off[c]];
              cube |= (val[c] >= iso_) << c;
            }
            ++st.cells_visited;
            if (cube == 0 || cube == 255) continue;
            int connected = 0;
            if (const int amb = ambiguous_faces(cube); amb && opt_.face_rule == FaceRule::decider)
              for (int f = 0; f < 6; ++f)
                if (amb >> f & 1) {
                  const auto& q = face_corners(f);
                  const double g0 = double(val[q[0]]) - iso_, g1 = double(val[q[1]]) - iso_,
                               g2 = double(val[q[2]]) - iso_, g3 = double(val[q[3]]) - iso_;
                  connected |= inside_connected(g0, g1, g2, g3) << f;
                }
            const CellLoops& cl = cell_loops(cube, connected);
            int at = 0;
            for (int l = 0; l < cl.count; ++l) {
              std::uint32_t ids[12];
              std::array<double, 3> pts[12];
              std::uint8_t faces[12];
              const int len = cl.length[l];
              for (int m = 0; m < len; ++m) {
                const int e = cl.edges[at + m];
                const EdgeInfo& info = edge_info(e);
                const std::size_t x = info.corner & 1, y = info.corner >> 1 & 1, z = info.corner >> 2 & 1;
                const Layer& L = z ? hi : lo;
                ids[m] = L.edge[info.axis][(i + x) + n_[0] * (j + y)];
                faces[m] = edge_faces(e) & kLowerFaces;
                if (len > 3)
                  pts[m] = crossing(i + x, j + y, k + z, info.axis, val[info.corner], val[info.corner | 1 << info.axis]);
              }
              if (!triangulate_loop(ids, pts, faces, len, opt_.triangulation, out)) {
                // A fan around a new vertex at the loop's centroid, numbered after all
                // crossings (marked here, renumbered once every job is done).
                std::array<double, 3> c{0, 0, 0};
                for (int m = 0; m < len; ++m)
                  for (int a = 0; a < 3; ++a) c[a] += pts[m][a] / len;
                const std::uint32_t cid = kCentroidMark | static_cast<std::uint32_t>(centroids.size() / 3);
                for (int a = 0; a < 3; ++a) centroids.push_back(static_cast<float>(c[a]));
                for (int m = 0; m < len; ++m) out.push_back({cid, ids[m], ids[(m + 1) % len]});
              }
              at += len;
            }
          }
      }
  }

  const ScalarGrid& g_;
  float iso_;
  ExtractOptions opt_;
  const MinMaxPyramid* pyr_;
  std::array<std::size_t, 3> n_, bn_;
  std::vector<std::size_t> row_base_;
  float* xyz_ = nullptr;
};

}  // namespace

Surface extract_isosurface(const ScalarGrid& grid, float iso, const ExtractOptions& options, const MinMaxPyramid* pyramid,
                           ExtractStats* stats) {
  if (grid.dims[0] < 2 || grid.dims[1] < 2 || grid.dims[2] < 2) return {};
  return Extractor(grid, iso, options, pyramid).run(stats);
}

}  // namespace fest::isosurface
