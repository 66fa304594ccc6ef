#include "formats/volume/mgh.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/volume/volume_geometry.hpp"
#include "formats/volume/voxel_codec.hpp"

namespace fest::formats::volume_detail {

namespace {

enum Offset : std::size_t {
  kVersion = 0, kDims = 4, kType = 20, kDof = 24, kGoodRas = 28, kSpacing = 30, kMdc = 42, kCras = 78,
};
constexpr std::size_t kFixedHeader = 90;  // the fields above; zeros up to kMghDataOffset

std::uint32_t be32(std::string_view b, std::size_t off) noexcept {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data()) + off;
  return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
         static_cast<std::uint32_t>(p[2]) << 8 | p[3];
}
std::int32_t be_i32(std::string_view b, std::size_t off) noexcept { return static_cast<std::int32_t>(be32(b, off)); }
std::int16_t be_i16(std::string_view b, std::size_t off) noexcept {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data()) + off;
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(p[0] << 8 | p[1]));
}
double be_f32(std::string_view b, std::size_t off) noexcept {
  const std::uint32_t bits = be32(b, off);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

void put_be32(std::string& out, std::size_t off, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out[off + i] = static_cast<char>((v >> (24 - 8 * i)) & 0xff);
}
void put_be_f32(std::string& out, std::size_t off, double v) {
  const auto f = static_cast<float>(storable_value(v, ScalarType::f32));
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_be32(out, off, bits);
}

std::optional<ScalarType> type_of_code(std::int32_t code) noexcept {
  switch (code) {
    case 0: return ScalarType::u8;
    case 1: return ScalarType::i32;
    case 3: return ScalarType::f32;
    case 4: return ScalarType::i16;
    default: return std::nullopt;
  }
}

const char* unsupported_code_name(std::int32_t code) noexcept {
  switch (code) {
    case 2: return "MRI_LONG";
    case 5: return "MRI_BITMAP";
    case 6: return "MRI_TENSOR";
    case 10: return "MRI_USHRT";
    default: return nullptr;
  }
}

// The four sizes and the voxel type, checked; nullopt (with a message) when unusable.
struct MghShape {
  std::uint64_t n[4];
  ScalarType type;
};
std::optional<MghShape> shape_of(std::string_view b, std::string* why) {
  auto fail = [&](std::string msg) -> std::optional<MghShape> {
    if (why) *why = std::move(msg);
    return std::nullopt;
  };
  if (b.size() < kFixedHeader) return fail(fmt::format("MGH header: the file has {} bytes, the header needs {}", b.size(), kFixedHeader));
  if (be_i32(b, kVersion) != 1) return fail(fmt::format("MGH header: version is {}, expected 1", be_i32(b, kVersion)));
  MghShape s{};
  static const char* names[] = {"width", "height", "depth", "nframes"};
  std::uint64_t count = 1;
  for (int i = 0; i < 4; ++i) {
    const std::int32_t d = be_i32(b, kDims + 4 * i);
    if (d <= 0) return fail(fmt::format("MGH header: {} = {} is not a positive size", names[i], d));
    s.n[i] = static_cast<std::uint64_t>(d);
    count *= s.n[i];  // each factor < 2^31 and the product is checked at every step
    if (count > kMaxVoxels) return fail(fmt::format("MGH header: {}x{}x{}x{} voxels exceed the limit of {} voxels",
                                                    be_i32(b, kDims), be_i32(b, kDims + 4), be_i32(b, kDims + 8),
                                                    be_i32(b, kDims + 12), kMaxVoxels));
  }
  const std::int32_t code = be_i32(b, kType);
  const std::optional<ScalarType> t = type_of_code(code);
  if (!t) {
    if (const char* name = unsupported_code_name(code))
      return fail(fmt::format("MGH header: data type {} ({}) is not supported; uint8, int16, int32 and float32 only", code, name));
    return fail(fmt::format("MGH header: unknown data type {}", code));
  }
  s.type = *t;
  const std::uint64_t needed = count * scalar_type_size(s.type);
  if (b.size() < kMghDataOffset || needed > b.size() - kMghDataOffset)
    return fail(fmt::format("MGH data truncated: {}x{}x{}x{} {} voxels need {} bytes after offset {}, the file has {}", s.n[0],
                            s.n[1], s.n[2], s.n[3], scalar_type_name(s.type), needed, kMghDataOffset,
                            b.size() < kMghDataOffset ? 0 : b.size() - kMghDataOffset));
  return s;
}

}  // namespace

bool looks_like_mgh(std::string_view bytes) noexcept {
  try {
    return shape_of(bytes, nullptr).has_value();
  } catch (...) {
    return false;
  }
}

Volume read_mgh(std::string_view b) {
  std::string why;
  const std::optional<MghShape> s = shape_of(b, &why);
  if (!s) throw bad_input("{}", why);
  Volume v;
  v.type = s->type;
  v.resize(static_cast<std::size_t>(s->n[0]), static_cast<std::size_t>(s->n[1]), static_cast<std::size_t>(s->n[2]),
           static_cast<std::size_t>(s->n[3]));
  decode_voxels(b.substr(kMghDataOffset), s->type, true, v.voxels);

  double spacing[3] = {1, 1, 1}, mdc[9] = {-1, 0, 0, 0, 0, 1, 0, -1, 0}, c_ras[3] = {0, 0, 0};
  if (be_i16(b, kGoodRas) != 0) {
    for (int i = 0; i < 3; ++i) spacing[i] = be_f32(b, kSpacing + 4 * i);
    for (int i = 0; i < 9; ++i) mdc[i] = be_f32(b, kMdc + 4 * i);
    for (int i = 0; i < 3; ++i) c_ras[i] = be_f32(b, kCras + 4 * i);
    for (double x : spacing)
      if (!std::isfinite(x)) throw bad_input("MGH header: a voxel size is not finite");
    for (double x : c_ras)
      if (!std::isfinite(x)) throw bad_input("MGH header: c_ras is not finite");
  }
  std::array<Vec3, 3> axes{};
  for (int c = 0; c < 3; ++c) axes[c] = {mdc[3 * c] * spacing[c], mdc[3 * c + 1] * spacing[c], mdc[3 * c + 2] * spacing[c]};
  set_axes(v, axes, "MGH direction cosines (Mdc) times voxel sizes");
  // c_ras is the world position of voxel dims/2 (not (dims-1)/2: FreeSurfer's centre).
  for (int r = 0; r < 3; ++r) {
    double o = c_ras[r];
    for (int c = 0; c < 3; ++c) o -= axes[c][static_cast<std::size_t>(r)] * static_cast<double>(s->n[c]) / 2.0;
    v.origin[static_cast<std::size_t>(r)] = o;
  }
  // The footer's first number is TR in milliseconds; it is the frame step of a series.
  const std::size_t footer = kMghDataOffset + static_cast<std::size_t>(v.voxels.size() * scalar_type_size(s->type));
  if (v.frames > 1 && b.size() >= footer + 4) {
    const double tr = be_f32(b, footer);
    if (std::isfinite(tr) && tr > 0) v.frame_spacing = tr / 1000.0;
  }
  return v;
}

std::string write_mgh(const Volume& volume, ScalarType type) {
  check_writable(volume, "MGH writer");
  std::int32_t code = 0;
  ScalarType stored = type;
  switch (type) {
    case ScalarType::u8: code = 0; break;
    case ScalarType::i8: stored = ScalarType::i16, code = 4; break;
    case ScalarType::i16: code = 4; break;
    case ScalarType::u16: stored = ScalarType::i32, code = 1; break;
    case ScalarType::i32: code = 1; break;
    case ScalarType::f32: code = 3; break;
    default:
      throw bad_input("MGH stores uint8, int16, int32 and float32 values, not {}; choose one with --type "
                      "(a narrower type may clip or round)",
                      scalar_type_name(type));
  }
  for (std::size_t d : volume.dims)
    if (d > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      throw bad_input("MGH cannot store a dimension of {}", d);
  std::string out(kMghDataOffset, '\0');
  put_be32(out, kVersion, 1);
  for (int i = 0; i < 3; ++i) put_be32(out, kDims + 4 * i, static_cast<std::uint32_t>(volume.dims[static_cast<std::size_t>(i)]));
  put_be32(out, kDims + 12, static_cast<std::uint32_t>(volume.frames));
  put_be32(out, kType, static_cast<std::uint32_t>(code));
  out[kGoodRas + 1] = 1;
  for (int c = 0; c < 3; ++c) {
    put_be_f32(out, kSpacing + 4 * c, volume.spacing[static_cast<std::size_t>(c)]);
    for (int r = 0; r < 3; ++r) put_be_f32(out, kMdc + 4 * (3 * c + r), volume.direction[static_cast<std::size_t>(3 * r + c)]);
  }
  for (int r = 0; r < 3; ++r) {
    double centre = volume.origin[static_cast<std::size_t>(r)];
    for (int c = 0; c < 3; ++c)
      centre += volume.direction[static_cast<std::size_t>(3 * r + c)] * volume.spacing[static_cast<std::size_t>(c)] *
                static_cast<double>(volume.dims[static_cast<std::size_t>(c)]) / 2.0;
    put_be_f32(out, kCras + 4 * r, centre);
  }
  out += encode_voxels(volume.voxels, stored, true);
  // Footer: TR (ms), flip angle, TE, TI, as nibabel writes it.
  std::string footer(16, '\0');
  if (volume.frames > 1) put_be_f32(footer, 0, volume.frame_spacing * 1000.0);
  out += footer;
  return out;
}

}  // namespace fest::formats::volume_detail
