#pragma once
// Placement helpers shared by the volume formats: every format states its axes as
// "direction times spacing" vectors in some world frame, and fest keeps RAS+ unit
// directions plus spacings.

#include <array>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

using Vec3 = std::array<double, 3>;

// Sets volume.spacing and volume.direction from three axis vectors (each the world step
// of one voxel along that axis). Throws bad_input naming `what` when a vector is zero or
// not finite.
void set_axes(Volume& volume, const std::array<Vec3, 3>& axes, const char* what);

// World step of one voxel along axis c: direction column c times spacing c.
Vec3 axis_step(const Volume& volume, int c) noexcept;

// The unit normal of two axes, for 2-D data whose third axis the file does not state.
Vec3 unit_normal(const Vec3& a, const Vec3& b) noexcept;

// LPS <-> RAS: negates the x and y world components of the origin and of every axis.
void flip_xy(Volume& volume) noexcept;

// Checks what a writer relies on: the voxel count matches the dimensions.
void check_writable(const Volume& volume, const char* what);

}  // namespace fest::formats::volume_detail
