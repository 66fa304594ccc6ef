// segbrain synth: the synthetic T1 head phantom and its truth labels (segbrain(1)).
#include <fmt/format.h>

#include "core/resources.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "segbrain/phantom.hpp"
#include "volume_files.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

namespace {

// A volume on the phantom's grid, centred on the world origin.
Volume grid_volume(const Grid& g) {
  Volume v;
  v.resize(g.n[0], g.n[1], g.n[2]);
  v.spacing = g.spacing;
  for (int a = 0; a < 3; ++a) v.origin[a] = -0.5 * double(g.n[a] - 1) * g.spacing[a];
  return v;
}

// Bytes a voxel costs while the phantom is made and written: its T1 (float) and truth
// (byte), both again as the double voxels of the two volumes written, and the encoded
// copies of the writers -- 4 + 1 + 8 + 8, rounded up to 32.
constexpr double kSynthBytesPerVoxel = 32;

}  // namespace

int run_synth(const SynthArgs& a) {
  if (a.phantom.noise < 0 || a.phantom.bias < 0) throw usage_error("--noise and --bias must be >= 0");
  const auto& n = a.phantom.size;
  check_fits_in_memory(static_cast<double>(n[0]) * static_cast<double>(n[1]) * static_cast<double>(n[2]) *
                                kSynthBytesPerVoxel,
                            fmt::format("a phantom of --size {},{},{} voxels", n[0], n[1], n[2]));
  Phantom p = make_phantom(a.phantom);
  Volume img = grid_volume(p.grid);
  img.type = ScalarType::f32;
  img.voxels.assign(p.t1.begin(), p.t1.end());
  Volume truth = grid_volume(p.grid);
  truth.type = ScalarType::u8;
  truth.voxels.assign(p.truth.begin(), p.truth.end());
  write_volume_output(img, a.output, std::nullopt);
  write_volume_output(truth, a.truth, std::nullopt);
  return 0;
}

}  // namespace fest::segbrain_tool
