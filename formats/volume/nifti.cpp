#include "formats/volume/nifti.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "core/error.hpp"
#include "formats/volume/volume_geometry.hpp"
#include "formats/volume/voxel_codec.hpp"

namespace fest::formats::volume_detail {

namespace {

constexpr std::size_t kHeaderSize = 348;
constexpr std::size_t kDataOffset = 352;  // header + the 4-byte "no extensions" flag

// Field offsets of the NIfTI-1 header (nifti1.h).
enum Offset : std::size_t {
  kSizeofHdr = 0, kRegular = 38, kDim = 40, kDatatype = 70, kBitpix = 72, kPixdim = 76,
  kVoxOffset = 108, kSclSlope = 112, kSclInter = 116, kXyztUnits = 123, kDescrip = 148,
  kQformCode = 252, kSformCode = 254, kQuatern = 256, kSrow = 280, kMagic = 344,
};

// NIfTI datatype codes (nifti1.h DT_*).
struct DatatypeCode {
  int code;
  ScalarType type;
};
constexpr DatatypeCode kDatatypes[] = {
    {2, ScalarType::u8},     {4, ScalarType::i16},    {8, ScalarType::i32},   {16, ScalarType::f32},
    {64, ScalarType::f64},   {256, ScalarType::i8},   {512, ScalarType::u16}, {768, ScalarType::u32},
    {1024, ScalarType::i64}, {1280, ScalarType::u64},
};

const char* unsupported_datatype_name(int code) noexcept {
  switch (code) {
    case 0: return "unknown (0)";
    case 1: return "binary (1 bit)";
    case 32: return "complex64";
    case 128: return "RGB24";
    case 1536: return "float128";
    case 1792: return "complex128";
    case 2048: return "complex256";
    case 2304: return "RGBA32";
    default: return nullptr;
  }
}

// Reads header fields in the file's byte order.
class HeaderView {
 public:
  HeaderView(std::string_view bytes, bool big_endian) : p_(reinterpret_cast<const unsigned char*>(bytes.data())), big_(big_endian) {}
  std::uint32_t u32(std::size_t off) const noexcept {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(p_[off + (big_ ? 3 - i : i)]) << (8 * i);
    return v;
  }
  std::int32_t i32(std::size_t off) const noexcept { return static_cast<std::int32_t>(u32(off)); }
  std::int16_t i16(std::size_t off) const noexcept {
    const unsigned v = big_ ? (p_[off] << 8u) | p_[off + 1] : (p_[off + 1] << 8u) | p_[off];
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(v));
  }
  double f32(std::size_t off) const noexcept {
    const std::uint32_t bits = u32(off);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  unsigned u8(std::size_t off) const noexcept { return p_[off]; }

 private:
  const unsigned char* p_;
  bool big_;
};

std::uint32_t read_le32(std::string_view bytes) noexcept { return HeaderView(bytes, false).u32(0); }
std::uint32_t read_be32(std::string_view bytes) noexcept { return HeaderView(bytes, true).u32(0); }

// Millimetres per the file's spatial unit (xyzt_units bits 0-2); "unknown" is taken as
// mm, as every NIfTI reader does.
double unit_to_mm(unsigned xyzt_units) noexcept {
  switch (xyzt_units & 0x07) {
    case 1: return 1000.0;  // metre
    case 3: return 0.001;   // micron
    default: return 1.0;    // unknown, mm
  }
}

// pixdim entries that are zero, negative or NaN mean "no spacing stated": 1, as in
// nifti1_io.
double usable_spacing(double pixdim) noexcept { return std::isfinite(pixdim) && pixdim > 0 ? pixdim : 1.0; }

// Geometry from the quaternion form (NIfTI "method 2"), following nifti_quatern_to_mat44.
void set_qform(Volume& v, const HeaderView& h, double mm) {
  double b = h.f32(kQuatern), c = h.f32(kQuatern + 4), d = h.f32(kQuatern + 8);
  const double qx = h.f32(kQuatern + 12), qy = h.f32(kQuatern + 16), qz = h.f32(kQuatern + 20);
  for (double x : {b, c, d, qx, qy, qz})
    if (!std::isfinite(x)) throw bad_input("NIfTI header: qform quaternion or offset is not finite");
  double a = 1.0 - (b * b + c * c + d * d);
  if (a < 1e-7) {  // a quaternion slightly longer than 1 from float rounding: renormalise
    const double s = 1.0 / std::sqrt(b * b + c * c + d * d);
    b *= s, c *= s, d *= s, a = 0.0;
  } else {
    a = std::sqrt(a);
  }
  const double qfac = h.f32(kPixdim) < 0 ? -1.0 : 1.0;
  const double r[9] = {a * a + b * b - c * c - d * d, 2 * (b * c - a * d),           2 * (b * d + a * c) * qfac,
                       2 * (b * c + a * d),           a * a + c * c - b * b - d * d, 2 * (c * d - a * b) * qfac,
                       2 * (b * d - a * c),           2 * (c * d + a * b),           (a * a + d * d - c * c - b * b) * qfac};
  for (int i = 0; i < 9; ++i) v.direction[i] = r[i];
  for (int c2 = 0; c2 < 3; ++c2) v.spacing[c2] = usable_spacing(h.f32(kPixdim + 4 * (c2 + 1))) * mm;
  v.origin = {qx * mm, qy * mm, qz * mm};
}

// Geometry from the affine rows (NIfTI "method 3").
void set_sform(Volume& v, const HeaderView& h, double mm) {
  double m[12];
  for (int i = 0; i < 12; ++i) {
    m[i] = h.f32(kSrow + 4 * i) * mm;
    if (!std::isfinite(m[i])) throw bad_input("NIfTI header: srow_{}[{}] is not finite", "xyz"[i / 4], i % 4);
  }
  std::array<Vec3, 3> axes{};
  for (int c = 0; c < 3; ++c) axes[c] = {m[c], m[4 + c], m[8 + c]};
  set_axes(v, axes, "NIfTI sform");
  v.origin = {m[3], m[7], m[11]};
}

bool sform_usable(const HeaderView& h) noexcept {
  // A zero column (a 2-D file with srow z all zero, say) leaves the axis undefined;
  // such files fall back to the qform, which always defines three axes.
  for (int c = 0; c < 3; ++c) {
    const double x = h.f32(kSrow + 4 * c), y = h.f32(kSrow + 16 + 4 * c), z = h.f32(kSrow + 32 + 4 * c);
    if (x == 0.0 && y == 0.0 && z == 0.0) return false;
  }
  return true;
}

void put16(std::string& h, std::size_t off, std::int16_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  h[off] = static_cast<char>(u & 0xff);
  h[off + 1] = static_cast<char>(u >> 8);
}
void put32(std::string& h, std::size_t off, std::uint32_t u) {
  for (int i = 0; i < 4; ++i) h[off + i] = static_cast<char>((u >> (8 * i)) & 0xff);
}
void putf(std::string& h, std::size_t off, double v) {
  // storable_value saturates first: a direct cast of an out-of-range double is UB.
  const auto f = static_cast<float>(storable_value(v, ScalarType::f32));
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put32(h, off, bits);
}

// Orthonormal right- or left-handed frame nearest the (possibly sheared) direction,
// by Gram-Schmidt; the qform can only state a rotation (and a flip through qfac).
std::array<Vec3, 3> orthonormal_frame(const Volume& v) {
  std::array<Vec3, 3> e{};
  for (int c = 0; c < 3; ++c) e[c] = {v.direction[c], v.direction[3 + c], v.direction[6 + c]};
  auto dot = [](const Vec3& p, const Vec3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < c; ++k) {
      const double t = dot(e[c], e[k]);
      for (int r = 0; r < 3; ++r) e[c][r] -= t * e[k][r];
    }
    const double n = std::sqrt(dot(e[c], e[c]));
    if (!std::isfinite(n) || n < 1e-9) return {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    for (int r = 0; r < 3; ++r) e[c][r] /= n;
  }
  return e;
}

// Quaternion of a rotation matrix, as nifti_mat44_to_quatern computes it.
void rotation_to_quaternion(const double r[9], double& b, double& c, double& d) {
  const double r11 = r[0], r12 = r[1], r13 = r[2], r21 = r[3], r22 = r[4], r23 = r[5], r31 = r[6], r32 = r[7], r33 = r[8];
  double a = r11 + r22 + r33 + 1.0;
  if (a > 0.5) {
    a = 0.5 * std::sqrt(a);
    b = 0.25 * (r32 - r23) / a;
    c = 0.25 * (r13 - r31) / a;
    d = 0.25 * (r21 - r12) / a;
  } else {
    const double xd = 1.0 + r11 - (r22 + r33), yd = 1.0 + r22 - (r11 + r33), zd = 1.0 + r33 - (r11 + r22);
    if (xd > 1.0) {
      b = 0.5 * std::sqrt(xd);
      c = 0.25 * (r12 + r21) / b;
      d = 0.25 * (r13 + r31) / b;
      a = 0.25 * (r32 - r23) / b;
    } else if (yd > 1.0) {
      c = 0.5 * std::sqrt(yd);
      b = 0.25 * (r12 + r21) / c;
      d = 0.25 * (r23 + r32) / c;
      a = 0.25 * (r13 - r31) / c;
    } else {
      d = 0.5 * std::sqrt(zd);
      b = 0.25 * (r13 + r31) / d;
      c = 0.25 * (r23 + r32) / d;
      a = 0.25 * (r21 - r12) / d;
    }
    if (a < 0.0) b = -b, c = -c, d = -d;
  }
}

}  // namespace

Volume read_nifti(std::string_view bytes) {
  if (bytes.size() < kHeaderSize)
    throw bad_input("NIfTI header: the file has {} bytes, a NIfTI-1 header needs {}", bytes.size(), kHeaderSize);
  bool big = false;
  if (read_le32(bytes) == kHeaderSize) {
    big = false;
  } else if (read_be32(bytes) == kHeaderSize) {
    big = true;
  } else if (read_le32(bytes) == 540 || read_be32(bytes) == 540) {
    throw bad_input("NIfTI-2 files are not supported (sizeof_hdr 540); save as NIfTI-1");
  } else {
    throw bad_input("NIfTI header: sizeof_hdr is {}, expected 348", static_cast<std::int32_t>(read_le32(bytes)));
  }
  const std::string_view magic = bytes.substr(kMagic, 4);
  if (magic == std::string_view("ni1\0", 4))
    throw bad_input("NIfTI header: two-file NIfTI (.hdr/.img, magic \"ni1\") is not supported; use a single .nii");
  if (magic != std::string_view("n+1\0", 4))
    throw bad_input("NIfTI header: magic at byte 344 is not \"n+1\" (an ANALYZE 7.5 file?)");

  const HeaderView h(bytes, big);
  const int ndim = h.i16(kDim);
  if (ndim < 1 || ndim > 7) throw bad_input("NIfTI header: dim[0] = {} is outside 1..7", ndim);
  int dim[8] = {ndim, 1, 1, 1, 1, 1, 1, 1};
  for (int i = 1; i <= ndim; ++i) {
    dim[i] = h.i16(kDim + 2 * i);
    if (dim[i] <= 0) throw bad_input("NIfTI header: dim[{}] = {} is not a positive size", i, dim[i]);
  }
  for (int i = 4; i <= ndim; ++i)
    if (dim[i] > 1)
      throw bad_input("NIfTI: {}-D data is not supported (dim[{}] = {}); only 3-D volumes (dim[4..7] = 1) are read",
                      i, i, dim[i]);

  const int code = h.i16(kDatatype);
  const DatatypeCode* found = nullptr;
  for (const DatatypeCode& d : kDatatypes)
    if (d.code == code) found = &d;
  if (found == nullptr) {
    if (const char* name = unsupported_datatype_name(code))
      throw bad_input("NIfTI header: datatype {} ({}) is not supported; scalar integer and float types only", code, name);
    throw bad_input("NIfTI header: unknown datatype code {}", code);
  }
  const ScalarType type = found->type;

  const double vox_offset = h.f32(kVoxOffset);
  if (!std::isfinite(vox_offset) || vox_offset < static_cast<double>(kHeaderSize) || vox_offset != std::floor(vox_offset))
    throw bad_input("NIfTI header: vox_offset {} is not a whole byte offset of at least 348", vox_offset);
  if (vox_offset > static_cast<double>(bytes.size()))
    throw bad_input("NIfTI header: vox_offset {} lies beyond the end of the file ({} bytes)", vox_offset, bytes.size());
  const auto offset = static_cast<std::size_t>(vox_offset);

  // Dimensions are int16, so the byte count fits comfortably in 64 bits.
  const std::uint64_t count = static_cast<std::uint64_t>(dim[1]) * dim[2] * dim[3];
  const std::uint64_t needed = count * scalar_type_size(type);
  if (needed > bytes.size() - offset)
    throw bad_input("NIfTI data truncated: {}x{}x{} {} voxels need {} bytes after offset {}, the file has {}", dim[1],
                    dim[2], dim[3], scalar_type_name(type), needed, offset, bytes.size() - offset);

  Volume v;
  v.type = type;
  v.resize(static_cast<std::size_t>(dim[1]), static_cast<std::size_t>(dim[2]), static_cast<std::size_t>(dim[3]));
  decode_voxels(bytes.substr(offset), type, big, v.voxels);

  const double slope = h.f32(kSclSlope);
  double inter = h.f32(kSclInter);
  if (!std::isfinite(inter)) inter = 0.0;
  if (std::isfinite(slope) && slope != 0.0 && (slope != 1.0 || inter != 0.0)) {
    for (double& x : v.voxels) x = x * slope + inter;
    // Scaled values are no longer the stored integers; keep them as floats so a write
    // does not round them back (float64 where float32 could lose 32-bit integers).
    v.type = scalar_type_size(type) <= 2 || type == ScalarType::f32 ? ScalarType::f32 : ScalarType::f64;
  }

  const double mm = unit_to_mm(h.u8(kXyztUnits));
  const int qform_code = h.i16(kQformCode), sform_code = h.i16(kSformCode);
  if (sform_code > 0 && sform_usable(h)) {
    set_sform(v, h, mm);
  } else if (qform_code > 0) {
    set_qform(v, h, mm);
  } else {
    for (int c = 0; c < 3; ++c) v.spacing[c] = usable_spacing(h.f32(kPixdim + 4 * (c + 1))) * mm;
  }
  return v;
}

std::string write_nifti(const Volume& volume, ScalarType type) {
  check_writable(volume, "NIfTI writer");
  for (int c = 0; c < 3; ++c)
    if (volume.dims[c] > static_cast<std::size_t>(std::numeric_limits<std::int16_t>::max()))
      throw bad_input("NIfTI-1 cannot store a dimension of {} (at most 32767)", volume.dims[c]);
  std::string h(kDataOffset, '\0');
  put32(h, kSizeofHdr, kHeaderSize);
  h[kRegular] = 'r';
  put16(h, kDim, 3);
  for (int i = 1; i <= 3; ++i) put16(h, kDim + 2 * i, static_cast<std::int16_t>(volume.dims[i - 1]));
  for (int i = 4; i <= 7; ++i) put16(h, kDim + 2 * i, 1);
  for (const DatatypeCode& d : kDatatypes)
    if (d.type == type) put16(h, kDatatype, static_cast<std::int16_t>(d.code));
  put16(h, kBitpix, static_cast<std::int16_t>(8 * scalar_type_size(type)));

  // qform: the rotation part of the direction; qfac carries a reflection.
  std::array<Vec3, 3> e = orthonormal_frame(volume);
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[1][0] * (e[0][1] * e[2][2] - e[0][2] * e[2][1]) +
                     e[2][0] * (e[0][1] * e[1][2] - e[0][2] * e[1][1]);
  const double qfac = det < 0 ? -1.0 : 1.0;
  const double r[9] = {e[0][0], e[1][0], e[2][0] * qfac, e[0][1], e[1][1], e[2][1] * qfac, e[0][2], e[1][2], e[2][2] * qfac};
  double b = 0, c = 0, d = 0;
  rotation_to_quaternion(r, b, c, d);

  putf(h, kPixdim, qfac);
  for (int i = 1; i <= 3; ++i) putf(h, kPixdim + 4 * i, volume.spacing[i - 1]);
  for (int i = 4; i <= 7; ++i) putf(h, kPixdim + 4 * i, 1.0);
  putf(h, kVoxOffset, static_cast<double>(kDataOffset));
  putf(h, kSclSlope, 1.0);
  putf(h, kSclInter, 0.0);
  h[kXyztUnits] = 2;  // NIFTI_UNITS_MM
  std::memcpy(&h[kDescrip], "fest", 4);
  put16(h, kQformCode, 1);  // NIFTI_XFORM_SCANNER_ANAT: the one code that means "world"
  put16(h, kSformCode, 1);
  putf(h, kQuatern, b);
  putf(h, kQuatern + 4, c);
  putf(h, kQuatern + 8, d);
  for (int i = 0; i < 3; ++i) putf(h, kQuatern + 12 + 4 * i, volume.origin[i]);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col)
      putf(h, kSrow + 16 * row + 4 * col, volume.direction[3 * row + col] * volume.spacing[col]);
    putf(h, kSrow + 16 * row + 12, volume.origin[row]);
  }
  std::memcpy(&h[kMagic], "n+1\0", 4);
  h += encode_voxels(volume.voxels, type, false);
  return h;
}

}  // namespace fest::formats::volume_detail
