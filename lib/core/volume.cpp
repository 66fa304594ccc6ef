#include "core/volume.hpp"

#include "core/error.hpp"

namespace fest {

const char* scalar_type_name(ScalarType t) noexcept {
  switch (t) {
    case ScalarType::u8: return "uint8";
    case ScalarType::i8: return "int8";
    case ScalarType::u16: return "uint16";
    case ScalarType::i16: return "int16";
    case ScalarType::u32: return "uint32";
    case ScalarType::i32: return "int32";
    case ScalarType::u64: return "uint64";
    case ScalarType::i64: return "int64";
    case ScalarType::f32: return "float32";
    case ScalarType::f64: return "float64";
  }
  return "unknown";
}

std::size_t scalar_type_size(ScalarType t) noexcept {
  switch (t) {
    case ScalarType::u8:
    case ScalarType::i8: return 1;
    case ScalarType::u16:
    case ScalarType::i16: return 2;
    case ScalarType::u32:
    case ScalarType::i32:
    case ScalarType::f32: return 4;
    case ScalarType::u64:
    case ScalarType::i64:
    case ScalarType::f64: return 8;
  }
  return 0;
}

bool scalar_type_is_integer(ScalarType t) noexcept {
  return t != ScalarType::f32 && t != ScalarType::f64;
}

bool parse_scalar_type(const std::string& name, ScalarType& out) noexcept {
  static const ScalarType all[] = {ScalarType::u8,  ScalarType::i8,  ScalarType::u16, ScalarType::i16,
                                   ScalarType::u32, ScalarType::i32, ScalarType::u64, ScalarType::i64,
                                   ScalarType::f32, ScalarType::f64};
  for (ScalarType t : all) {
    if (name == scalar_type_name(t)) {
      out = t;
      return true;
    }
  }
  return false;
}

std::array<double, 3> Volume::world(double i, double j, double k) const noexcept {
  const double v[3] = {i * spacing[0], j * spacing[1], k * spacing[2]};
  std::array<double, 3> w{};
  for (int r = 0; r < 3; ++r)
    w[r] = origin[r] + direction[3 * r + 0] * v[0] + direction[3 * r + 1] * v[1] + direction[3 * r + 2] * v[2];
  return w;
}

void Volume::resize(std::size_t nx, std::size_t ny, std::size_t nz, std::size_t nt) {
  if (nx == 0 || ny == 0 || nz == 0) throw bad_input("volume has a zero dimension ({}x{}x{})", nx, ny, nz);
  if (nt == 0) throw bad_input("volume has zero frames ({}x{}x{}x0)", nx, ny, nz);
  if (nx > kMaxVoxels || ny > kMaxVoxels || nz > kMaxVoxels ||
      static_cast<std::uint64_t>(nx) * ny > kMaxVoxels ||
      static_cast<std::uint64_t>(nx) * ny * nz > kMaxVoxels)
    throw bad_input("volume of {}x{}x{} voxels exceeds the limit of {} voxels", nx, ny, nz, kMaxVoxels);
  if (nt > kMaxVoxels || static_cast<std::uint64_t>(nx) * ny * nz * nt > kMaxVoxels)
    throw bad_input("volume of {}x{}x{}x{} voxels exceeds the limit of {} voxels", nx, ny, nz, nt, kMaxVoxels);
  dims = {nx, ny, nz};
  frames = nt;
  voxels.assign(nx * ny * nz * nt, 0.0);
}

Volume Volume::frame(std::size_t t) const {
  if (t >= frames) throw bad_input("frame {} does not exist: the volume has {} frame(s), numbered 0..{}", t, frames, frames - 1);
  Volume out;
  out.dims = dims;
  out.spacing = spacing;
  out.origin = origin;
  out.direction = direction;
  out.type = type;
  const std::size_t n = frame_size();
  out.voxels.assign(voxels.begin() + static_cast<std::ptrdiff_t>(t * n), voxels.begin() + static_cast<std::ptrdiff_t>((t + 1) * n));
  return out;
}

void Volume::require_3d(const char* who) const {
  if (frames > 1)
    throw bad_input("{} works on one 3-D volume, and the input is a 4-D series of {} frames of {}x{}x{}; "
                    "take one frame of it with fconv first",
                    who, frames, dims[0], dims[1], dims[2]);
}

}  // namespace fest
