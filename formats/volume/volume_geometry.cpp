#include "formats/volume/volume_geometry.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::formats::volume_detail {

void set_axes(Volume& volume, const std::array<Vec3, 3>& axes, const char* what) {
  for (int c = 0; c < 3; ++c) {
    const Vec3& a = axes[c];
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!std::isfinite(norm) || norm == 0.0)
      throw bad_input("{}: axis {} has no usable direction ({}, {}, {})", what, c, a[0], a[1], a[2]);
    volume.spacing[c] = norm;
    for (int r = 0; r < 3; ++r) volume.direction[3 * r + c] = a[r] / norm;
  }
}

Vec3 axis_step(const Volume& volume, int c) noexcept {
  return {volume.direction[c] * volume.spacing[c], volume.direction[3 + c] * volume.spacing[c],
          volume.direction[6 + c] * volume.spacing[c]};
}

Vec3 unit_normal(const Vec3& a, const Vec3& b) noexcept {
  Vec3 n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!std::isfinite(norm) || norm == 0.0) return {0, 0, 1};
  return {n[0] / norm, n[1] / norm, n[2] / norm};
}

void flip_xy(Volume& volume) noexcept {
  // "0.0 - v" rather than "-v" so zeros stay +0 and files do not say "-0".
  volume.origin[0] = 0.0 - volume.origin[0];
  volume.origin[1] = 0.0 - volume.origin[1];
  for (int c = 0; c < 3; ++c) {
    volume.direction[c] = 0.0 - volume.direction[c];
    volume.direction[3 + c] = 0.0 - volume.direction[3 + c];
  }
}

void check_writable(const Volume& volume, const char* what) {
  const std::size_t n = volume.frame_size();
  if (volume.dims[0] == 0 || volume.dims[1] == 0 || volume.dims[2] == 0 || volume.frames == 0 ||
      n / volume.dims[0] / volume.dims[1] != volume.dims[2] || volume.voxels.size() / volume.frames != n ||
      volume.voxels.size() % volume.frames != 0)
    throw bad_input("{}: volume of {}x{}x{}x{} holds {} voxels", what, volume.dims[0], volume.dims[1], volume.dims[2],
                    volume.frames, volume.voxels.size());
}

}  // namespace fest::formats::volume_detail
