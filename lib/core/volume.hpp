#pragma once
// A 3-D scalar grid with physical placement, or a series of such grids (a 4-D volume:
// fMRI time series, diffusion directions): the in-memory volume of fest.
//
// Conventions (every reader and writer converts to these):
//  * voxels are stored x fastest, then y, then z: index = x + nx*(y + ny*z); a 4-D
//    volume stores its `frames` 3-D frames one after the other, so frame t starts at
//    t * frame_size() and a 3-D volume is the 4-D one with frames == 1;
//  * world coordinates are RAS+ millimetres (x to the Right, y Anterior, z Superior),
//    as in NIfTI; LPS formats (MetaImage, NRRD "left-posterior-superior") are flipped
//    on input and output;
//  * world(i,j,k) = origin + direction * diag(spacing) * (i,j,k), where the columns of
//    `direction` are the unit directions of the three voxel axes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fest {

enum class ScalarType { u8, i8, u16, i16, u32, i32, u64, i64, f32, f64 };

const char* scalar_type_name(ScalarType t) noexcept;   // "uint8", "int16", "float32", ...
std::size_t scalar_type_size(ScalarType t) noexcept;   // bytes per value
bool scalar_type_is_integer(ScalarType t) noexcept;
// Parses the names above; returns false when unknown.
bool parse_scalar_type(const std::string& name, ScalarType& out) noexcept;

struct Volume {
  std::array<std::size_t, 3> dims{0, 0, 0};
  // The fourth axis: the number of 3-D frames, and the step between two frames as the
  // file states it (NIfTI pixdim[4] converted to seconds when the file names a time
  // unit, MGH's TR in seconds, the fourth spacing of NRRD and MetaImage).
  std::size_t frames = 1;
  double frame_spacing = 1.0;
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  // Row-major 3x3; column c is the world direction of voxel axis c.
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};
  // The type the values were stored as, and will be written as unless told otherwise.
  ScalarType type = ScalarType::f32;
  // Values after any scaling the file declares (NIfTI scl_slope/scl_inter).
  std::vector<double> voxels;

  // Voxels of one frame, and of the whole volume (all frames).
  std::size_t frame_size() const noexcept { return dims[0] * dims[1] * dims[2]; }
  std::size_t size() const noexcept { return frame_size() * frames; }
  std::size_t index(std::size_t x, std::size_t y, std::size_t z) const noexcept {
    return x + dims[0] * (y + dims[1] * z);
  }
  double& at(std::size_t x, std::size_t y, std::size_t z) { return voxels[index(x, y, z)]; }
  double at(std::size_t x, std::size_t y, std::size_t z) const { return voxels[index(x, y, z)]; }

  // World position (RAS mm) of the centre of voxel (i, j, k).
  std::array<double, 3> world(double i, double j, double k) const noexcept;

  // Allocates dims (and frames) and zero voxels; throws Status::bad_input for absurd
  // sizes (a zero or an overflow), so readers can call it straight with header values.
  void resize(std::size_t nx, std::size_t ny, std::size_t nz, std::size_t nt = 1);

  // Frame t (0-based) as a 3-D volume with the same placement; throws bad_input when t
  // is not a frame of this volume.
  Volume frame(std::size_t t) const;

  // For code that handles one 3-D grid only: throws bad_input naming `who` and the frame
  // count when this is a 4-D series, so a fourth dimension is never dropped silently.
  void require_3d(const char* who) const;
};

// Largest voxel count a reader accepts before reading data (2^31: 16 GiB as doubles).
constexpr std::uint64_t kMaxVoxels = 1ull << 31;

}  // namespace fest
