#include "formats/volume/nifti.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include <nifti2_io.h>

#include "core/error.hpp"
#include "formats/volume/volume_geometry.hpp"
#include "formats/volume/voxel_codec.hpp"

namespace fest::formats::volume_detail {

namespace {

enum class NiftiKind { analyze, nifti1, nifti2 };

struct NiftiHeaderFacts {
  NiftiKind kind = NiftiKind::nifti1;
  bool pair = false;        // data in a separate .img file (magic ni1/ni2, or Analyze)
  bool big_endian = false;
};

static_assert(sizeof(nifti_1_header) == 348, "nifti_1_header must be the 348-byte file layout");
static_assert(sizeof(nifti_2_header) == 540, "nifti_2_header must be the 540-byte file layout");

constexpr std::size_t kHeaderSize = 348;
constexpr std::size_t kHeader2Size = 540;
constexpr std::size_t kDataOffset = 352;   // header + the 4-byte "no extensions" flag
constexpr std::size_t kData2Offset = 544;  // the same for NIfTI-2

// Field offsets of the NIfTI-1 header (nifti1.h); Analyze 7.5 shares the first 148 bytes.
enum Offset : std::size_t {
  kSizeofHdr = 0, kRegular = 38, kDim = 40, kDatatype = 70, kBitpix = 72, kPixdim = 76,
  kVoxOffset = 108, kSclSlope = 112, kSclInter = 116, kXyztUnits = 123, kDescrip = 148,
  kOriginator = 253,  // Analyze (SPM): five int16 at an odd offset, the origin voxel (1-based)
  kQformCode = 252, kSformCode = 254, kQuatern = 256, kSrow = 280, kMagic = 344,
};
// NIfTI-2 offsets (nifti2.h).
enum Offset2 : std::size_t {
  k2Magic = 4, k2Datatype = 12, k2Dim = 16, k2Pixdim = 104, k2VoxOffset = 168,
};

// NIfTI datatype codes (nifti1.h DT_*); Analyze uses the same codes for its types.
struct DatatypeCode {
  int code;
  ScalarType type;
};
constexpr DatatypeCode kDatatypes[] = {
    {2, ScalarType::u8},     {4, ScalarType::i16},    {8, ScalarType::i32},   {16, ScalarType::f32},
    {64, ScalarType::f64},   {256, ScalarType::i8},   {512, ScalarType::u16}, {768, ScalarType::u32},
    {1024, ScalarType::i64}, {1280, ScalarType::u64},
};

int datatype_code(ScalarType t) noexcept {
  for (const DatatypeCode& d : kDatatypes)
    if (d.type == t) return d.code;
  return 0;
}

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
  std::uint64_t uint(std::size_t off, int n) const noexcept {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(p_[off + (big_ ? n - 1 - i : i)]) << (8 * i);
    return v;
  }
  std::uint32_t u32(std::size_t off) const noexcept { return static_cast<std::uint32_t>(uint(off, 4)); }
  std::int32_t i32(std::size_t off) const noexcept { return static_cast<std::int32_t>(u32(off)); }
  std::int64_t i64(std::size_t off) const noexcept { return static_cast<std::int64_t>(uint(off, 8)); }
  std::int16_t i16(std::size_t off) const noexcept { return static_cast<std::int16_t>(static_cast<std::uint16_t>(uint(off, 2))); }
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

// Millimetres per the file's spatial unit (xyzt_units bits 0-2); "unknown" is taken as
// mm, as every NIfTI reader does.
double unit_to_mm(int xyz_units) noexcept {
  switch (xyz_units) {
    case NIFTI_UNITS_METER: return 1000.0;
    case NIFTI_UNITS_MICRON: return 0.001;
    default: return 1.0;  // unknown, mm
  }
}

// Seconds per the file's time unit; other units (Hz, ppm, rad/s, unknown) keep the
// number as stated.
double unit_to_seconds(int time_units) noexcept {
  switch (time_units) {
    case NIFTI_UNITS_MSEC: return 1e-3;
    case NIFTI_UNITS_USEC: return 1e-6;
    default: return 1.0;
  }
}

// pixdim entries that are zero, negative or NaN mean "no spacing stated": 1, as in
// nifti_clib.
double usable_spacing(double pixdim) noexcept { return std::isfinite(pixdim) && pixdim > 0 ? pixdim : 1.0; }

struct NimDeleter {
  void operator()(nifti_image* nim) const noexcept { nifti_image_free(nim); }
};
using NimPtr = std::unique_ptr<nifti_image, NimDeleter>;

// Geometry from a 4x4 (qto_xyz or sto_xyz) of nifti_clib.
void set_from_matrix(Volume& v, const nifti_dmat44& m, double mm, const char* what) {
  std::array<Vec3, 3> axes{};
  for (int c = 0; c < 3; ++c) axes[c] = {m.m[0][c] * mm, m.m[1][c] * mm, m.m[2][c] * mm};
  set_axes(v, axes, what);
  v.origin = {m.m[0][3] * mm, m.m[1][3] * mm, m.m[2][3] * mm};
}

bool columns_nonzero(const nifti_dmat44& m) noexcept {
  // A zero column (a 2-D file with srow z all zero, say) leaves the axis undefined;
  // such files fall back to the qform, which always defines three axes.
  for (int c = 0; c < 3; ++c)
    if (m.m[0][c] == 0.0 && m.m[1][c] == 0.0 && m.m[2][c] == 0.0) return false;
  return true;
}

// Analyze 7.5 placement as SPM (and nibabel's Spm2AnalyzeImage) define it: voxel sizes
// from pixdim with x negated (Analyze stores images radiologically), and the origin
// voxel from the `originator` field when it lies in a plausible range, else the centre
// of the grid: world = diag(-dx, dy, dz) * (ijk - origin).
void set_analyze_geometry(Volume& v, const HeaderView& h) {
  double zoom[3], origin[3];
  bool use_originator = false;
  int orig[3];
  for (int c = 0; c < 3; ++c) {
    zoom[c] = h.f32(kPixdim + 4 * (c + 1));
    if (!std::isfinite(zoom[c])) throw bad_input("Analyze header: pixdim[{}] is not finite", c + 1);
    orig[c] = h.i16(kOriginator + 2 * c);
    if (orig[c] != 0) use_originator = true;
  }
  for (int c = 0; c < 3; ++c) {
    const double n = static_cast<double>(v.dims[c]);
    if (!(orig[c] > -n && orig[c] < 2 * n)) use_originator = false;
  }
  for (int c = 0; c < 3; ++c) origin[c] = use_originator ? orig[c] - 1.0 : (static_cast<double>(v.dims[c]) - 1.0) / 2.0;
  zoom[0] = -zoom[0];
  std::array<Vec3, 3> axes{};
  for (int c = 0; c < 3; ++c) {
    axes[c] = {0, 0, 0};
    // A zero voxel size would leave the axis undefined; take 1 as nifti_clib does.
    axes[c][static_cast<std::size_t>(c)] = zoom[c] == 0.0 ? (c == 0 ? -1.0 : 1.0) : zoom[c];
  }
  set_axes(v, axes, "Analyze pixdim");
  for (int c = 0; c < 3; ++c) v.origin[c] = 0.0 - origin[c] * axes[c][static_cast<std::size_t>(c)];
}

NiftiHeaderFacts facts_or_throw(std::string_view bytes) {
  if (bytes.size() < kHeaderSize)
    throw bad_input("NIfTI header: the file has {} bytes, a NIfTI-1 header needs {}", bytes.size(), kHeaderSize);
  const HeaderView le(bytes, false), be(bytes, true);
  NiftiHeaderFacts f;
  if (le.u32(0) == kHeaderSize || be.u32(0) == kHeaderSize) {
    f.big_endian = le.u32(0) != kHeaderSize;
    const std::string_view magic = bytes.substr(kMagic, 4);
    if (magic == std::string_view("n+1\0", 4)) {
      f.kind = NiftiKind::nifti1;
    } else if (magic == std::string_view("ni1\0", 4)) {
      f.kind = NiftiKind::nifti1, f.pair = true;
    } else if (magic[0] == 'n') {
      throw bad_input("NIfTI header: magic at byte 344 is not \"n+1\" (single file) or \"ni1\" (.hdr/.img pair)");
    } else {
      f.kind = NiftiKind::analyze, f.pair = true;  // Analyze 7.5 has no magic
    }
    return f;
  }
  if (le.u32(0) == kHeader2Size || be.u32(0) == kHeader2Size) {
    if (bytes.size() < kHeader2Size)
      throw bad_input("NIfTI-2 header: the file has {} bytes, a NIfTI-2 header needs {}", bytes.size(), kHeader2Size);
    f.big_endian = le.u32(0) != kHeader2Size;
    f.kind = NiftiKind::nifti2;
    // The magic is "n+2\0" or "ni2\0" and then \r\n\032\n, which detects transfers that
    // mangle line ends; nibabel and nifti_clib accept files whose last four bytes are
    // zero (nifti_clib 3.0 writes them so), and so does fest.
    const std::string_view magic = bytes.substr(k2Magic, 4);
    if (magic == std::string_view("n+2\0", 4))
      f.pair = false;
    else if (magic == std::string_view("ni2\0", 4))
      f.pair = true;
    else
      throw bad_input("NIfTI-2 header: magic at byte 4 is not \"n+2\" or \"ni2\"");
    const std::string_view eol = bytes.substr(k2Magic + 4, 4);
    if (eol != std::string_view("\r\n\032\n", 4) && eol != std::string_view("\0\0\0\0", 4))
      throw bad_input("NIfTI-2 header: bytes 8-11 are not \\r\\n\\032\\n: the file was damaged by a text-mode transfer");
    return f;
  }
  throw bad_input("NIfTI header: sizeof_hdr is {}, expected 348 (NIfTI-1, Analyze 7.5) or 540 (NIfTI-2)", le.i32(0));
}

// The scalar type of a datatype code, or a message naming what the code is.
ScalarType scalar_type_of(int code, const char* what) {
  for (const DatatypeCode& d : kDatatypes)
    if (d.code == code) return d.type;
  if (const char* name = unsupported_datatype_name(code))
    throw bad_input("{}: datatype {} ({}) is not supported; scalar integer and float types only", what, code, name);
  throw bad_input("{}: unknown datatype code {}", what, code);
}

// Byte offset of the voxels in the file that holds them, checked against its size.
std::size_t data_offset(const HeaderView& h, const NiftiHeaderFacts& f, std::size_t file_size, const char* what) {
  if (f.kind == NiftiKind::nifti2) {
    const std::int64_t off = h.i64(k2VoxOffset);
    const auto min = static_cast<std::int64_t>(f.pair ? 0 : kHeader2Size);
    if (off < min) throw bad_input("{}: vox_offset {} is less than {}", what, off, min);
    if (static_cast<std::uint64_t>(off) > file_size)
      throw bad_input("{}: vox_offset {} lies beyond the end of the {} ({} bytes)", what, off,
                      f.pair ? "image file" : "file", file_size);
    return static_cast<std::size_t>(off);
  }
  const double off = h.f32(kVoxOffset);
  const double min = f.pair ? 0.0 : static_cast<double>(kHeaderSize);
  if (!std::isfinite(off) || off < min || off != std::floor(off))
    throw bad_input("{}: vox_offset {} is not a whole byte offset of at least {}", what, off, min);
  if (off > static_cast<double>(file_size))
    throw bad_input("{}: vox_offset {} lies beyond the end of the {} ({} bytes)", what, off, f.pair ? "image file" : "file",
                    file_size);
  return static_cast<std::size_t>(off);
}

}  // namespace

Volume read_nifti(std::string_view bytes, const std::string_view* image) {
  const NiftiHeaderFacts f = facts_or_throw(bytes);
  const char* what = f.kind == NiftiKind::nifti2 ? "NIfTI-2 header" : f.kind == NiftiKind::analyze ? "Analyze header" : "NIfTI header";
  const HeaderView h(bytes, f.big_endian);
  const bool v2 = f.kind == NiftiKind::nifti2;

  // Checked here so that messages name the field, and so that nifti_clib (which prints
  // its own complaints) is only given headers it accepts.
  std::int64_t dim[8];
  for (int i = 0; i < 8; ++i) dim[i] = v2 ? h.i64(k2Dim + 8 * i) : h.i16(kDim + 2 * i);
  const std::int64_t ndim = dim[0];
  if (ndim < 1 || ndim > 7) throw bad_input("{}: dim[0] = {} is outside 1..7", what, ndim);
  for (int i = 1; i <= ndim; ++i)
    if (dim[i] <= 0) throw bad_input("{}: dim[{}] = {} is not a positive size", what, i, dim[i]);
  for (int i = 5; i <= ndim; ++i)
    if (dim[i] > 1)
      throw bad_input("{}: {}-D data is not supported (dim[{}] = {}: vector, tensor or other components per voxel); "
                      "fest reads 3-D volumes and 4-D series",
                      what, i, i, dim[i]);
  const ScalarType type = scalar_type_of(v2 ? h.i16(k2Datatype) : h.i16(kDatatype), what);

  // nifti_clib turns the header into NIfTI's image description (byte order, qform,
  // sform, scaling): the field's own reading of the header.
  NimPtr nim;
  if (v2) {
    nifti_2_header hdr;
    std::memcpy(&hdr, bytes.data(), sizeof hdr);
    nim.reset(nifti_convert_n2hdr2nim(hdr, nullptr));
  } else {
    nifti_1_header hdr;
    std::memcpy(&hdr, bytes.data(), sizeof hdr);
    nim.reset(nifti_convert_n1hdr2nim(hdr, nullptr));
  }
  if (!nim) throw bad_input("{}: nifti_clib refuses the header", what);

  std::uint64_t n[4] = {1, 1, 1, 1};
  for (int i = 0; i < 4 && i < ndim; ++i) n[i] = static_cast<std::uint64_t>(dim[i + 1]);
  // The byte count, saturating: a header claiming more than the file holds is
  // "truncated" whatever its size; the voxel limit is checked after.
  std::uint64_t count = 1, needed = 0;
  bool overflow = false;
  for (std::uint64_t d : n) overflow = overflow || __builtin_mul_overflow(count, d, &count);
  overflow = overflow || __builtin_mul_overflow(count, static_cast<std::uint64_t>(scalar_type_size(type)), &needed);

  // The voxels: after the header in a single file, in the .img of a pair.
  std::string_view data_file = bytes;
  if (f.pair) {
    if (image == nullptr)
      throw bad_input("{}: this is the header of a .hdr/.img pair, and its voxels are in the .img file beside it; "
                      "read the pair by its file name (standard input carries only one file)",
                      what);
    data_file = *image;
  }
  const std::size_t offset = data_offset(h, f, data_file.size(), what);
  if (overflow || needed > data_file.size() - offset)
    throw bad_input("{} data truncated: {}x{}x{}x{} {} voxels need {} bytes after offset {}, the {} has {}",
                    f.kind == NiftiKind::analyze ? "Analyze" : "NIfTI", n[0], n[1], n[2], n[3], scalar_type_name(type),
                    overflow ? std::string("more than 2^64") : std::to_string(needed), offset,
                    f.pair ? "image file" : "file", data_file.size() - offset);

  Volume v;
  v.type = type;
  v.resize(static_cast<std::size_t>(n[0]), static_cast<std::size_t>(n[1]), static_cast<std::size_t>(n[2]),
           static_cast<std::size_t>(n[3]));
  decode_voxels(data_file.substr(offset), type, f.big_endian, v.voxels);

  // Scaling: NIfTI scl_slope/scl_inter; Analyze (SPM) keeps a scale factor in funused1.
  double slope = f.kind == NiftiKind::analyze ? h.f32(kSclSlope) : nim->scl_slope;
  double inter = f.kind == NiftiKind::analyze ? 0.0 : nim->scl_inter;
  if (!std::isfinite(inter)) inter = 0.0;
  if (std::isfinite(slope) && slope != 0.0 && (slope != 1.0 || inter != 0.0)) {
    for (double& x : v.voxels) x = x * slope + inter;
    // Scaled values are no longer the stored integers; keep them as floats so a write
    // does not round them back (float64 where float32 could lose 32-bit integers).
    v.type = scalar_type_size(type) <= 2 || type == ScalarType::f32 ? ScalarType::f32 : ScalarType::f64;
  }

  if (n[3] > 1) v.frame_spacing = usable_spacing(nim->dt) * unit_to_seconds(nim->time_units);

  if (f.kind == NiftiKind::analyze) {
    set_analyze_geometry(v, h);
    return v;
  }
  const double mm = unit_to_mm(nim->xyz_units);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c)
      if (nim->sform_code > 0 && !std::isfinite(nim->sto_xyz.m[r][c]))
        throw bad_input("{}: srow_{}[{}] is not finite", what, "xyz"[r], c);
  const bool sform_places = nim->sform_code > 0 && columns_nonzero(nim->sto_xyz);
  // Zero or negative sizes mean "not stated" (usable_spacing), but NaN or infinite ones
  // are damage: refuse them by name rather than write a spacing of 1 without a word.
  // nifti_clib has already put 1 in their place, so the header's own bytes are read.
  for (int c = 0; c < 3 && c < ndim && !sform_places; ++c) {
    double pixdim = 0;
    if (f.kind == NiftiKind::nifti2) {
      const std::uint64_t bits = h.uint(k2Pixdim + 8 * (c + 1), 8);
      std::memcpy(&pixdim, &bits, 8);
    } else {
      pixdim = h.f32(kPixdim + 4 * (c + 1));
    }
    if (!std::isfinite(pixdim))
      throw bad_input("{}: pixdim[{}] (voxel size along axis {}) is {}, not a finite number", what, c + 1, "xyz"[c],
                      pixdim);
  }
  if (sform_places) {
    set_from_matrix(v, nim->sto_xyz, mm, "NIfTI sform");
  } else if (nim->qform_code > 0) {
    for (double x : {nim->quatern_b, nim->quatern_c, nim->quatern_d, nim->qoffset_x, nim->qoffset_y, nim->qoffset_z})
      if (!std::isfinite(x)) throw bad_input("{}: qform quaternion or offset is not finite", what);
    // The qform is a rotation (with qfac's flip) times the voxel sizes: nifti_clib's
    // rotation for unit sizes gives the directions exactly, and the sizes are taken as
    // written, rather than recovered from column lengths (which differ in the last bit).
    const nifti_dmat44 r = nifti_quatern_to_dmat44(nim->quatern_b, nim->quatern_c, nim->quatern_d, 0.0, 0.0, 0.0,
                                                   1.0, 1.0, 1.0, nim->qfac);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) v.direction[static_cast<std::size_t>(3 * row + c)] = r.m[row][c];
    for (int c = 0; c < 3; ++c) v.spacing[c] = usable_spacing(nim->pixdim[c + 1]) * mm;
    v.origin = {nim->qoffset_x * mm, nim->qoffset_y * mm, nim->qoffset_z * mm};
  } else {
    // NIfTI "method 1": no world placement stated, only voxel sizes.
    for (int c = 0; c < 3; ++c) v.spacing[c] = usable_spacing(nim->pixdim[c + 1]) * mm;
  }
  return v;
}

namespace {

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


// The NIfTI-1 header bytes (with the 4-byte extension flag) for a single file or, with
// `pair`, for the .hdr of a pair (magic "ni1", data from byte 0 of the .img).
std::string nifti1_header(const Volume& volume, ScalarType type, bool pair) {
  check_writable(volume, "NIfTI writer");
  for (int c = 0; c < 3; ++c)
    if (volume.dims[c] > static_cast<std::size_t>(std::numeric_limits<std::int16_t>::max()))
      throw bad_input("NIfTI-1 cannot store a dimension of {} (at most 32767; NIfTI-2 can: --to nifti2)", volume.dims[c]);
  if (volume.frames > static_cast<std::size_t>(std::numeric_limits<std::int16_t>::max()))
    throw bad_input("NIfTI-1 cannot store {} frames (at most 32767; NIfTI-2 can: --to nifti2)", volume.frames);
  const bool series = volume.frames > 1;
  std::string h(kDataOffset, '\0');
  put32(h, kSizeofHdr, kHeaderSize);
  h[kRegular] = 'r';
  put16(h, kDim, series ? 4 : 3);
  for (int i = 1; i <= 3; ++i) put16(h, kDim + 2 * i, static_cast<std::int16_t>(volume.dims[i - 1]));
  for (int i = 4; i <= 7; ++i) put16(h, kDim + 2 * i, 1);
  if (series) put16(h, kDim + 8, static_cast<std::int16_t>(volume.frames));
  put16(h, kDatatype, static_cast<std::int16_t>(datatype_code(type)));
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
  if (series) putf(h, kPixdim + 16, volume.frame_spacing);
  putf(h, kVoxOffset, pair ? 0.0 : static_cast<double>(kDataOffset));
  putf(h, kSclSlope, 1.0);
  putf(h, kSclInter, 0.0);
  h[kXyztUnits] = series ? NIFTI_UNITS_MM | NIFTI_UNITS_SEC : NIFTI_UNITS_MM;
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
  std::memcpy(&h[kMagic], pair ? "ni1\0" : "n+1\0", 4);
  return h;
}

}  // namespace

std::string write_nifti(const Volume& volume, ScalarType type) {
  std::string h = nifti1_header(volume, type, false);
  h += encode_voxels(volume.voxels, type, false);
  return h;
}

NiftiPairBytes write_nifti_pair(const Volume& volume, ScalarType type) {
  return {nifti1_header(volume, type, true), encode_voxels(volume.voxels, type, false)};
}

// NIfTI-2 through nifti_clib: an image description filled from the volume, turned into
// the 540-byte header by nifti_convert_nim2n2hdr (which also writes the magic).
std::string write_nifti2(const Volume& volume, ScalarType type) {
  check_writable(volume, "NIfTI-2 writer");
  const bool series = volume.frames > 1;
  const std::int64_t dims[8] = {series ? 4 : 3, static_cast<std::int64_t>(volume.dims[0]),
                                static_cast<std::int64_t>(volume.dims[1]), static_cast<std::int64_t>(volume.dims[2]),
                                static_cast<std::int64_t>(volume.frames), 1, 1, 1};
  NimPtr nim(nifti_make_new_nim(dims, datatype_code(type), 0));
  if (!nim) throw runtime_failure("nifti_clib could not describe a {}x{}x{}x{} volume", dims[1], dims[2], dims[3], dims[4]);
  double* spacing[3] = {&nim->dx, &nim->dy, &nim->dz};
  for (int c = 0; c < 3; ++c) *spacing[c] = nim->pixdim[c + 1] = volume.spacing[c];
  nim->dt = nim->pixdim[4] = series ? volume.frame_spacing : 1.0;
  nim->xyz_units = NIFTI_UNITS_MM;
  nim->time_units = series ? NIFTI_UNITS_SEC : NIFTI_UNITS_UNKNOWN;
  nim->scl_slope = 1.0;
  nim->scl_inter = 0.0;
  std::strcpy(nim->descrip, "fest");

  std::array<Vec3, 3> e = orthonormal_frame(volume);
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[1][0] * (e[0][1] * e[2][2] - e[0][2] * e[2][1]) +
                     e[2][0] * (e[0][1] * e[1][2] - e[0][2] * e[1][1]);
  nim->qfac = det < 0 ? -1.0 : 1.0;
  const double r[9] = {e[0][0], e[1][0], e[2][0] * nim->qfac, e[0][1], e[1][1], e[2][1] * nim->qfac,
                       e[0][2], e[1][2], e[2][2] * nim->qfac};
  rotation_to_quaternion(r, nim->quatern_b, nim->quatern_c, nim->quatern_d);
  nim->qoffset_x = volume.origin[0];
  nim->qoffset_y = volume.origin[1];
  nim->qoffset_z = volume.origin[2];
  nim->qform_code = nim->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) nim->sto_xyz.m[row][col] = volume.direction[3 * row + col] * volume.spacing[col];
    nim->sto_xyz.m[row][3] = volume.origin[row];
  }
  nim->nifti_type = NIFTI_FTYPE_NIFTI2_1;
  nim->iname_offset = static_cast<std::int64_t>(kData2Offset);

  nifti_2_header hdr;
  if (nifti_convert_nim2n2hdr(nim.get(), &hdr) != 0) throw runtime_failure("nifti_clib could not write a NIfTI-2 header");
  std::string out(kData2Offset, '\0');
  std::memcpy(out.data(), &hdr, sizeof hdr);
  std::memcpy(&out[k2Magic], "n+2\0\r\n\032\n", 8);  // the full magic of the standard
  out += encode_voxels(volume.voxels, type, false);
  return out;
}

}  // namespace fest::formats::volume_detail
