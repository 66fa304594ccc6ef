#include "radiosity/hemicube.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::radiosity {
namespace {

// Task t: which local axis is the view direction z, the horizontal x and the vertical y,
// with signs, and the y range of its half face (in units of z).
struct TaskFrame {
  int zx, xx, yx;      // indices into local (u, v, n)
  double zs;           // sign of the view axis
  double ylo, yhi;
  bool top;
};
constexpr TaskFrame kFrames[6] = {
    {2, 0, 1, 1.0, -1.0, 0.0, true},  {2, 0, 1, 1.0, 0.0, 1.0, true},   // top halves: z = n
    {0, 1, 2, 1.0, 0.0, 1.0, false},  {0, 1, 2, -1.0, 0.0, 1.0, false},  // sides +u, -u
    {1, 0, 2, 1.0, 0.0, 1.0, false},  {1, 0, 2, -1.0, 0.0, 1.0, false},  // sides +v, -v
};

struct V {
  double x, y, z;
};

}  // namespace

void tangent_frame(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  const Eigen::Vector3d a = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX()
                            : std::abs(n.y()) < 0.6 ? Eigen::Vector3d::UnitY()
                                                    : Eigen::Vector3d::UnitZ();
  u = a.cross(n).normalized();
  v = n.cross(u);
}

Hemicube::Hemicube(int resolution) : res_(resolution) {
  if (resolution < 2 || resolution % 2 != 0)
    throw bad_input("hemicube resolution {} must be even and at least 2", resolution);
  const int h = res_, hh = res_ / 2;
  const double d = 2.0 / h, da = d * d;
  std::vector<double> raw[6];
  raw_sum_ = 0;
  for (int t = 0; t < 6; ++t) {
    raw[t].resize(static_cast<std::size_t>(h) * hh);
    for (int iy = 0; iy < hh; ++iy)
      for (int ix = 0; ix < h; ++ix) {
        const double x = -1 + (ix + 0.5) * d;
        const double y = kFrames[t].ylo + (iy + 0.5) * d;
        const double q = x * x + y * y + 1;
        const double f = kFrames[t].top ? da / (M_PI * q * q) : y * da / (M_PI * q * q);
        raw[t][static_cast<std::size_t>(iy) * h + ix] = f;
        raw_sum_ += f;
      }
  }
  for (int t = 0; t < 6; ++t) {
    tasks_[t].dff.resize(raw[t].size());
    for (std::size_t i = 0; i < raw[t].size(); ++i) tasks_[t].dff[i] = static_cast<float>(raw[t][i] / raw_sum_);
    tasks_[t].depth.resize(raw[t].size());
    tasks_[t].id.resize(raw[t].size());
  }
}

void Hemicube::project(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                       const std::vector<const Polygon*>& items, const std::vector<std::uint8_t>& draw, double near,
                       int threads, std::vector<double>& ff, std::vector<double>* coverage,
                       std::vector<double>* visible) {
  Eigen::Vector3d u, v;
  tangent_frame(normal, u, v);
  const std::size_t n = items.size();
  local_.resize(4 * n);
  item_id_.assign(n, -2);
  for (std::size_t k = 0; k < n; ++k) {
    if (!draw[k]) continue;
    const Polygon& p = *items[k];
    bool above = false;
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int c = 0; c < p.n; ++c) {
      const Eigen::Vector3d d = p.p[c] - centre;
      local_[4 * k + c] = {d.dot(u), d.dot(v), d.dot(normal)};
      if (local_[4 * k + c].z() > 0) above = true;
      s += p.p[c].cross(p.p[(c + 1) % p.n]);
    }
    if (!above) continue;  // entirely behind the hemicube's base plane
    // Facing away from the centre: still an occluder, receives nothing.
    const bool front = s.dot(centre - p.p[0]) > 0;
    item_id_[k] = front ? static_cast<std::int32_t>(k) : -1;
  }
  parallel_for(6, threads, [&](std::size_t t) { run_task(static_cast<int>(t), items, near, coverage != nullptr); });
  ff.assign(n, 0.0);
  for (int t = 0; t < 6; ++t)
    for (std::size_t k = 0; k < n; ++k) ff[k] += tasks_[t].row[k];
  if (coverage) {
    coverage->assign(n, 0.0);
    for (int t = 0; t < 6; ++t)
      for (std::size_t k = 0; k < n; ++k) (*coverage)[k] += tasks_[t].cover[k];
  }
  if (coverage && visible) {
    visible->assign(n, 0.0);
    for (int t = 0; t < 6; ++t)
      for (std::size_t k = 0; k < n; ++k) (*visible)[k] += tasks_[t].vis[k];
  }
}

void Hemicube::run_task(int t, const std::vector<const Polygon*>& items, double near, bool coverage) {
  Task& task = tasks_[t];
  const TaskFrame& fr = kFrames[t];
  const int w = res_, hh = res_ / 2;
  const double half = 0.5 * res_;
  std::fill(task.depth.begin(), task.depth.end(), 0.0f);  // 1/z: 0 is infinitely far
  std::fill(task.id.begin(), task.id.end(), std::numeric_limits<std::int32_t>::min());
  task.row.assign(items.size(), 0.0);
  if (coverage) {
    task.cover.assign(items.size(), 0.0);
    task.seen.assign(task.id.size(), -1);
    task.tie.assign(task.id.size(), -1);
  }
  double* cover = coverage ? task.cover.data() : nullptr;

  std::array<V, 12> a, b;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::int32_t id = item_id_[k];
    if (id == -2) continue;
    const int nc = items[k]->n;
    int na = 0;
    // Outcodes against the five clip planes: a polygon wholly outside one plane is
    // skipped, one wholly inside all of them needs no clipping (most polygons fall
    // in one of these for each of the six tasks).
    unsigned all_out = 0x1f, any_out = 0;
    for (int c = 0; c < nc; ++c) {
      const Eigen::Vector3d& l = local_[4 * k + c];
      const V q{l[fr.xx], l[fr.yx], fr.zs * l[fr.zx]};
      a[na++] = q;
      const unsigned code = (q.z - q.x < 0 ? 1u : 0u) | (q.z + q.x < 0 ? 2u : 0u) |
                            (q.y - fr.ylo * q.z < 0 ? 4u : 0u) | (fr.yhi * q.z - q.y < 0 ? 8u : 0u) |
                            (q.z - near < 0 ? 16u : 0u);
      all_out &= code;
      any_out |= code;
    }
    if (all_out != 0) continue;
    // Clip against z - x >= 0, z + x >= 0, y - ylo z >= 0, yhi z - y >= 0, z >= near.
    for (int plane = 0; plane < 5 && na >= 3 && any_out != 0; ++plane) {
      if (!(any_out & (1u << plane))) continue;
      auto dist = [&](const V& q) {
        switch (plane) {
          case 0: return q.z - q.x;
          case 1: return q.z + q.x;
          case 2: return q.y - fr.ylo * q.z;
          case 3: return fr.yhi * q.z - q.y;
          default: return q.z - near;
        }
      };
      int nb = 0;
      for (int c = 0; c < na; ++c) {
        const V& p = a[c];
        const V& q = a[(c + 1) % na];
        const double dp = dist(p), dq = dist(q);
        if (dp >= 0) b[nb++] = p;
        if ((dp >= 0) != (dq >= 0)) {
          const double s = dp / (dp - dq);
          b[nb++] = {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
        }
      }
      std::swap(a, b);
      na = nb;
    }
    if (na < 3) continue;
    // Project: sx in [0, H), sy in [0, H/2); w = 1/z is linear in screen space.
    double sx[12], sy[12], iz[12];
    for (int c = 0; c < na; ++c) {
      iz[c] = 1.0 / a[c].z;
      sx[c] = (a[c].x * iz[c] + 1) * half;
      sy[c] = (a[c].y * iz[c] - fr.ylo) * half;
    }
    for (int c = 1; c + 1 < na; ++c) {
      const int i0 = 0, i1 = c, i2 = c + 1;
      const double area = (sx[i1] - sx[i0]) * (sy[i2] - sy[i0]) - (sx[i2] - sx[i0]) * (sy[i1] - sy[i0]);
      if (std::abs(area) < 1e-12) continue;
      const double inv = 1.0 / area;
      const double minx = std::min({sx[i0], sx[i1], sx[i2]}), maxx = std::max({sx[i0], sx[i1], sx[i2]});
      const double miny = std::min({sy[i0], sy[i1], sy[i2]}), maxy = std::max({sy[i0], sy[i1], sy[i2]});
      const int x0 = std::max(0, static_cast<int>(std::ceil(minx - 0.5)));
      const int x1 = std::min(w - 1, static_cast<int>(std::floor(maxx - 0.5)));
      const int y0 = std::max(0, static_cast<int>(std::ceil(miny - 0.5)));
      const int y1 = std::min(hh - 1, static_cast<int>(std::floor(maxy - 0.5)));
      // Edge functions are linear along a row: w0 = a0 px + c0(py), w1 = a1 px + c1(py),
      // w2 = 1 - w0 - w1. Each row's span where all three are >= -eps is solved for
      // directly, so no pixel outside the triangle is visited. A small tolerance: a
      // pixel centre on an edge shared by two polygons must not fall through both by
      // rounding (overlaps are settled by the depth test).
      const double eps = 1e-7;
      const double a0 = (sy[i1] - sy[i2]) * inv, a1 = (sy[i2] - sy[i0]) * inv, a2 = -a0 - a1;
      const double k0 = (sx[i1] * sy[i2] - sx[i2] * sy[i1]) * inv, m0 = (sx[i2] - sx[i1]) * inv;
      const double k1 = (sx[i2] * sy[i0] - sx[i0] * sy[i2]) * inv, m1 = (sx[i0] - sx[i2]) * inv;
      const std::int32_t key = static_cast<std::int32_t>(k);
      const std::int32_t stored = id >= 0 ? id : -key - 2;  // occluders stored as -(k+2)
      for (int iy = y0; iy <= y1; ++iy) {
        const double py = iy + 0.5;
        const double c0 = k0 + m0 * py, c1 = k1 + m1 * py, c2 = 1 - c0 - c1;
        double lo = x0 + 0.5, hi = x1 + 0.5;
        bool empty = false;
        auto limit = [&](double ai, double ci) {
          if (ai > 0) lo = std::max(lo, (-eps - ci) / ai);
          else if (ai < 0) hi = std::min(hi, (-eps - ci) / ai);
          else if (ci < -eps) empty = true;
        };
        limit(a0, c0);
        limit(a1, c1);
        limit(a2, c2);
        if (empty || lo > hi) continue;
        const int xa = std::max(x0, static_cast<int>(std::ceil(lo - 0.5)));
        const int xb = std::min(x1, static_cast<int>(std::floor(hi - 0.5)));
        for (int ix = xa; ix <= xb; ++ix) {
          const double px = ix + 0.5;
          const double w0 = a0 * px + c0, w1 = a1 * px + c1, w2 = 1 - w0 - w1;
          if (w0 < -eps || w1 < -eps || w2 < -eps) continue;  // rounding at the span ends
          const float d = static_cast<float>(w0 * iz[i0] + w1 * iz[i1] + w2 * iz[i2]);
          const std::size_t pix = static_cast<std::size_t>(iy) * w + ix;
          if (cover && id >= 0 && task.seen[pix] != key) {
            cover[k] += task.dff[pix];
            task.seen[pix] = key;
          }
          // Nearest wins; on equal depth the lower item (occluders count by their index).
          const std::int32_t cur = task.id[pix];
          const std::int32_t cur_key = cur == std::numeric_limits<std::int32_t>::min() ? cur : (cur >= 0 ? cur : -cur - 2);
          const float old = task.depth[pix];
          if (cover && std::abs(d - old) <= 1e-5f * old) {
            // A depth tie (neighbours meeting at an edge): the lower item wins, the other
            // is remembered as visible too.
            if (key < cur_key) {
              task.tie[pix] = cur >= 0 ? cur : -1;
              task.depth[pix] = d;
              task.id[pix] = stored;
            } else if (key != cur_key) {
              task.tie[pix] = id;
            }
          } else if (d > old || (d == old && key < cur_key)) {
            task.depth[pix] = d;
            task.id[pix] = stored;
            if (cover) task.tie[pix] = -1;
          }
        }
      }
    }
  }
  for (std::size_t pix = 0; pix < task.id.size(); ++pix)
    if (task.id[pix] >= 0) task.row[static_cast<std::size_t>(task.id[pix])] += task.dff[pix];
  if (coverage) {
    task.vis = task.row;
    for (std::size_t pix = 0; pix < task.id.size(); ++pix)
      if (task.tie[pix] >= 0) task.vis[static_cast<std::size_t>(task.tie[pix])] += task.dff[pix];
  }
}

}  // namespace fest::radiosity
