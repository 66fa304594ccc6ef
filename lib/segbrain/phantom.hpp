#pragma once
// The synthetic T1 head of `segbrain synth` (spec §5, simplified in this version): an
// ellipsoidal head on a neck, scalp fat, skull, subarachnoid CSF, a gyrified cortex,
// white matter, two ventricles and two eyes, with Rician noise and a multiplicative
// bias field; truth labels use the numbering of spec §2.6.

#include <cstdint>
#include <vector>

#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct PhantomOptions {
  std::array<std::size_t, 3> size{160, 192, 160};
  std::array<double, 3> spacing{1, 1, 1};
  double noise = 0.03;   // noise sd as a fraction of the white-matter intensity
  double bias = 0.2;     // peak-to-peak of the multiplicative bias field
  std::uint64_t seed = 1;
};

struct Phantom {
  Grid grid;             // RAS voxel axes, centred on the world origin
  Image t1;
  std::vector<std::uint8_t> truth;  // 0 air, 1 extracranial, 2 subarachnoid CSF, 3 brain, 6 ventricles, 10 eye
};

Phantom make_phantom(const PhantomOptions& o);

}  // namespace fest::segbrain
