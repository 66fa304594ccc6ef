#pragma once
// Multiscale edges of a volume (docs/volwave.md §6): the modulus maxima of the dyadic
// wavelet transform whose wavelets are the three partial derivatives of a smoothing
// function (Mallat & Zhong 1992, eqs. 5-8, extended to 3-D), chained across scales, as
// Westermann & Ertl (1997) use them to segment vessels in CT angiography.
//
//  * Smoothing: S_1 = h * f, S_{j+1} = h_j * S_j with the cubic B-spline filter
//    h = [1 4 6 4 1]/16 "a trous" (2^(j-1) - 1 zeros between taps) along x, y, z, so
//    S_j is f smoothed at scale sigma_j = sqrt((4^j - 1) / 3) voxels.
//  * Wavelet transform W_j = sigma_j * grad S_j (central differences); its modulus M_j
//    stays constant across scales at a step edge (Lipschitz alpha = 0), decays like
//    sigma^alpha for noise (alpha < 0) and grows for smooth ramps.
//  * Maxima: voxels where M_j is a strict local maximum along the gradient direction
//    (Mallat-Zhong's "modulus maxima"), M_j interpolated trilinearly at p +- u.
//  * Chains: a maximum at scale j is kept when a kept maximum of scale j+1 lies within
//    2^(j-1) voxels (the cone of influence), from the coarsest scale down; the finest
//    maxima that survive are the edges. alpha is estimated along the chain.
//  * Position: a parabola through M_1 at p - u, p, p + u gives the sub-voxel edge.

#include <array>
#include <cstdint>
#include <vector>

#include "core/progress_callback.hpp"
#include "core/volume.hpp"

namespace fest::wavelet {

struct EdgeOptions {
  int scales = 3;          // J
  double threshold = -1;   // minimum M_j; < 0: automatic (see edges.cpp)
  int min_scales = 0;      // chain through the first K scales (0: all J)
  int threads = 1;
  ProgressFn progress;     // z slices taken up by every scale's maxima and every chaining pass
};

struct EdgePoint {
  std::array<std::size_t, 3> voxel{0, 0, 0};
  std::array<double, 3> position{0, 0, 0};  // sub-voxel, in voxel coordinates
  double modulus = 0;                       // M_1 at the voxel
  double alpha = 0;                         // Lipschitz estimate along the chain
};

struct EdgeMap {
  std::vector<double> modulus;        // M_1 at edge voxels, 0 elsewhere (x fastest)
  std::vector<EdgePoint> points;      // the same edges, in voxel order
  double threshold = 0;               // the one used
  std::vector<std::size_t> maxima_per_scale;
};

// Throws bad_input for NaN or infinite voxels.
EdgeMap multiscale_edges(const Volume& volume, const EdgeOptions& options);

// sigma_j of the smoothing at scale j (1-based).
double scale_sigma(int j) noexcept;

}  // namespace fest::wavelet
