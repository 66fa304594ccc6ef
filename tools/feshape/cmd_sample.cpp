// feshape sample: synthetic points on a deformable superquadric (docs/feshape.md §4).
#include <cmath>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "feshape/sample.hpp"
#include "feshape/xyz_codec.hpp"
#include "model_args.hpp"

namespace fest::feshape_tool {

int run_sample(const SampleArgs& a) {
  if (a.model.qs.empty()) throw usage_error("sample needs --qs");
  const feshape::Model m = model_from_args(a.model);
  feshape::SampleOptions o;
  if (a.n < 1 || a.n > 100000000) throw usage_error("--n must be in 1..1e8");
  o.count = static_cast<std::size_t>(a.n);
  if (!(a.noise >= 0) || !std::isfinite(a.noise)) throw usage_error("--noise must be >= 0");
  o.noise = a.noise;
  if (!a.bumps.empty()) {
    if (a.bumps.size() != 2 || !(a.bumps[0] >= 0 && a.bumps[0] <= 1000) || a.bumps[0] != std::floor(a.bumps[0]) ||
        !std::isfinite(a.bumps[1]))
      throw usage_error("--bumps needs K,AMP (K whole, 0..1000)");
    o.bumps = static_cast<int>(a.bumps[0]);
    o.bump_amplitude = a.bumps[1];
  }
  o.seed = a.seed;
  write_output(a.output, feshape::encode_points(feshape::sample_points(m, o)));
  return 0;
}

}  // namespace fest::feshape_tool
