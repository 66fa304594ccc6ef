#include "sampling/mip_kernel.hpp"

#include <cmath>

#include "core/error.hpp"
#include "sampling/kernel.hpp"
#include "sampling/weight_table.hpp"

namespace fest::sampling {

namespace {

// One whole level: the linear-interpolation lookup at level L pulled back to level 0.
std::vector<double> level_weights(int level, double x, MipBuild build, int n0) {
  const int b = 1 << level;
  const int n_level = n0 / b;
  // Lookup at level L: texel j covers [j b, (j+1) b), centre (j + ½) b (docs/resample.md "Mip-mapping").
  const double t = x / b - 0.5;
  const double j0 = std::floor(t), phi = t - j0;
  std::vector<double> v(static_cast<std::size_t>(n_level), 0.0);
  auto wrap = [n_level](double j) { return static_cast<std::size_t>(((static_cast<long>(j) % n_level) + n_level) % n_level); };
  v[wrap(j0)] += 1 - phi;
  v[wrap(j0 + 1)] += phi;
  // Each reduction halves the size with the build kernel at the coarser level's rate
  // (box: the 2×2 average in 1-D; gaussian σ = ½ coarse texel), periodic at the ends.
  const Kernel k = make_kernel(build == MipBuild::box ? "box" : "gaussian:sigma=0.5");
  for (int l = level; l > 0; --l) {
    const int n_fine = n0 >> (l - 1), n_coarse = n0 >> l;
    const WeightTable w = make_weight_table(n_fine, n_coarse, k, 0, EdgeMode::wrap);
    std::vector<double> fine(static_cast<std::size_t>(n_fine), 0.0);
    for (int o = 0; o < n_coarse; ++o)
      for (std::size_t j = w.offset[static_cast<std::size_t>(o)]; j < w.offset[static_cast<std::size_t>(o) + 1]; ++j)
        fine[static_cast<std::size_t>(w.index[j])] += v[static_cast<std::size_t>(o)] * static_cast<double>(w.weight[j]);
    v.swap(fine);
  }
  return v;
}

}  // namespace

MipBuild parse_mip_build(const std::string& name) {
  if (name == "box") return MipBuild::box;
  if (name == "gaussian") return MipBuild::gaussian;
  throw usage_error("unknown pyramid build '{}' (box or gaussian)", name);
}

std::vector<double> mip_kernel_1d(double level, double x, MipBuild build, int blocks) {
  if (!(level >= 0 && level <= 16)) throw usage_error("mip kernel: level {} is out of range [0, 16]", level);
  if (!std::isfinite(x)) throw usage_error("mip kernel: position {} is not finite", x);
  if (blocks < 2 || blocks > 1024) throw usage_error("mip kernel: {} blocks is out of range [2, 1024]", blocks);
  const int lo = static_cast<int>(std::floor(level)), hi = static_cast<int>(std::ceil(level));
  const int n0 = (1 << hi) * blocks;
  const double xm = x - n0 * std::floor(x / n0);
  std::vector<double> w = level_weights(lo, xm, build, n0);
  if (hi != lo) {
    const double frac = level - lo;
    const std::vector<double> w2 = level_weights(hi, xm, build, n0);
    for (std::size_t i = 0; i < w.size(); ++i) w[i] = (1 - frac) * w[i] + frac * w2[i];
  }
  return w;
}

}  // namespace fest::sampling
