#pragma once
// The synthetic T1 head of `segbrain synth` (docs/segbrain.md §5, simplified in this version): an
// ellipsoidal head on a neck, scalp fat, skull, subarachnoid CSF, a gyrified cortex,
// white matter, two ventricles, two eyes and two optic nerves, with Rician noise and a
// multiplicative bias field; truth labels use the numbering of docs/segbrain.md §3-4.

#include <array>
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

// The optic nerves of the phantom: straight cylinders of radius kNerveRadiusMm (T1 100,
// between grey and white matter) from the posterior pole of each globe to one chiasm
// point on the midline, sheathed by 1.75 mm of CSF where they run inside the skull.
// Positions in mm relative to the grid centre (R, A, S), as the phantom draws them.
constexpr double kNerveRadiusMm = 1.75;
struct NerveSegment {
  std::array<double, 3> from, to;  // posterior pole of the globe, chiasm point
};
// Eye centres of the phantom (globe radius kEyeRadiusMm), left then right.
constexpr double kEyeRadiusMm = 12;
std::array<std::array<double, 3>, 2> phantom_eye_centres();
std::array<NerveSegment, 2> phantom_nerves();

struct Phantom {
  Grid grid;             // RAS voxel axes, centred on the world origin
  Image t1;
  std::vector<std::uint8_t> truth;  // 0 air, 1 extracranial, 2 subarachnoid CSF, 3 brain, 6 ventricles, 9 optic nerve, 10 eye
};

Phantom make_phantom(const PhantomOptions& o);

}  // namespace fest::segbrain
