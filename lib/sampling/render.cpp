#include "sampling/render.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "core/threads.hpp"

namespace fest::sampling {

namespace {

constexpr std::int64_t max_pixels = std::int64_t{1} << 31;

struct Sample {
  double x, y;  // absolute screen position
  double value;
};

// The samples of one row of pixels, in pixel order.
std::vector<Sample> row_samples(const Scene& scene, const RenderOptions& o, int py) {
  std::vector<Sample> row;
  row.reserve(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.samples));
  for (int px = 0; px < o.width; ++px)
    for (const Point2& p : pixel_samples(o.pattern, o.samples, o.seed, px, py)) {
      const double x = px + p.x, y = py + p.y;
      row.push_back({x, y, scene.value(x, y)});
    }
  return row;
}

void for_blocks(int rows, int threads, const std::function<void(int, int)>& body) {
  const int n = std::max(1, std::min(threads, rows));
  std::vector<std::thread> pool;
  for (int t = 0; t < n; ++t) {
    const int begin = static_cast<int>(static_cast<long long>(rows) * t / n);
    const int end = static_cast<int>(static_cast<long long>(rows) * (t + 1) / n);
    if (n == 1) {
      body(begin, end);
      return;
    }
    pool.emplace_back(body, begin, end);
  }
  for (auto& th : pool) th.join();
}

}  // namespace

FloatImage render(const Scene& scene, const RenderOptions& o) {
  if (o.width <= 0 || o.height <= 0) throw usage_error("render: size {}x{} must be positive", o.width, o.height);
  if (static_cast<std::int64_t>(o.width) * o.height > max_pixels)
    throw usage_error("render: size {}x{} exceeds 2^31 pixels", o.width, o.height);
  check_sample_count(o.pattern, o.samples);
  const Kernel& k = o.pixel_filter;
  if (!k.nearest && (!k.spatial || !std::isfinite(k.radius)))
    throw usage_error("render: pixel filter '{}' has no finite spatial form", k.name);
  if (!(o.filter_scale > 0 && o.filter_scale <= 64)) throw usage_error("render: pixel filter radius is out of range");
  const int threads = resolve_threads(o.threads);
  FloatImage out(o.width, o.height, 1);

  if (scene.analytic) {
    for_blocks(o.height, threads, [&](int begin, int end) {
      for (int y = begin; y < end; ++y)
        for (int x = 0; x < o.width; ++x) out.row(y)[x] = static_cast<float>(scene.value(x + 0.5, y + 0.5));
    });
    return out;
  }

  // Point sampling or a box of half-width ≤ ½ reads only the pixel's own samples.
  const double reach = k.nearest ? 0.5 : k.radius * o.filter_scale;
  const int rings = std::max(0, static_cast<int>(std::ceil(reach - 0.5)));
  for_blocks(o.height, threads, [&](int begin, int end) {
    // A window of sample rows [y - rings, y + rings], each computed once per block.
    std::vector<std::vector<Sample>> window;
    int first = begin - rings;
    for (int r = first; r <= begin + rings; ++r)
      window.push_back(r >= 0 && r < o.height ? row_samples(scene, o, r) : std::vector<Sample>{});
    for (int y = begin; y < end; ++y) {
      if (y > begin) {
        window.erase(window.begin());
        ++first;
        const int r = y + rings;
        window.push_back(r < o.height ? row_samples(scene, o, r) : std::vector<Sample>{});
      }
      for (int x = 0; x < o.width; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        double sum = 0, wsum = 0;
        for (const auto& row : window) {
          if (row.empty()) continue;
          const std::size_t lo = static_cast<std::size_t>(std::max(0, x - rings)) * static_cast<std::size_t>(o.samples);
          const std::size_t hi = static_cast<std::size_t>(std::min(o.width - 1, x + rings) + 1) * static_cast<std::size_t>(o.samples);
          for (std::size_t i = lo; i < hi; ++i) {
            const Sample& s = row[i];
            double w = 1;
            if (!k.nearest) w = k.spatial((s.x - cx) / o.filter_scale) * k.spatial((s.y - cy) / o.filter_scale);
            sum += w * s.value;
            wsum += w;
          }
        }
        // A filter whose weights cancel (all samples on negative lobes) falls back to the
        // pixel's plain mean rather than dividing by zero.
        if (std::fabs(wsum) < 1e-12) {
          sum = 0;
          const auto& own = window[static_cast<std::size_t>(rings)];
          for (int i = 0; i < o.samples; ++i) sum += own[static_cast<std::size_t>(x * o.samples + i)].value;
          wsum = o.samples;
        }
        out.row(y)[x] = static_cast<float>(sum / wsum);
      }
    }
  });
  return out;
}

}  // namespace fest::sampling
