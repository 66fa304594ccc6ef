#include "formats/detect.hpp"
#include "core/quote.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <optional>

#include "core/error.hpp"

namespace fest::formats {

namespace {

struct FormatRow {
  Format format;
  Kind kind;
  const char* name;       // the --to name
  const char* extension;  // written by default
  const char* aliases;    // other names and extensions accepted, space separated
};

constexpr FormatRow kFormats[] = {
    {Format::ply, Kind::mesh, "ply", ".ply", ""},
    {Format::obj, Kind::mesh, "obj", ".obj", ""},
    {Format::off, Kind::mesh, "off", ".off", ""},
    {Format::stl, Kind::mesh, "stl", ".stl", ""},
    {Format::drc, Kind::mesh, "drc", ".drc", "draco"},
    {Format::png, Kind::image, "png", ".png", ""},
    {Format::pgm, Kind::image, "pgm", ".pgm", ""},
    {Format::ppm, Kind::image, "ppm", ".ppm", "pnm"},
    {Format::pam, Kind::image, "pam", ".pam", ""},
    {Format::pfm, Kind::image, "pfm", ".pfm", ""},
    {Format::exr, Kind::image, "exr", ".exr", "openexr"},
    {Format::tiff, Kind::image, "tiff", ".tif", "tif"},
    {Format::jpeg, Kind::image, "jpeg", ".jpg", "jpg"},
    {Format::nifti, Kind::volume, "nifti", ".nii", "nii"},
    {Format::nrrd, Kind::volume, "nrrd", ".nrrd", ""},
    {Format::mha, Kind::volume, "mha", ".mha", "metaimage"},
    {Format::nifti2, Kind::volume, "nifti2", ".nii", "nii2"},
    {Format::nifti_pair, Kind::volume, "hdr", ".hdr", "nifti-pair img"},
    {Format::analyze, Kind::volume, "analyze", ".hdr", ""},
    {Format::mgh, Kind::volume, "mgh", ".mgh", ""},  // ".mgz": mgh + gzip, see gzip_alias()
    {Format::vtu, Kind::dataset, "vtu", ".vtu", ""},
    {Format::vti, Kind::dataset, "vti", ".vti", ""},
    {Format::vtp, Kind::dataset, "vtp", ".vtp", ""},
    {Format::vtk, Kind::dataset, "vtk", ".vtk", ""},
    {Format::vts, Kind::dataset, "vts", ".vts", ""},
    {Format::csv, Kind::table, "csv", ".csv", ""},
    {Format::tsv, Kind::table, "tsv", ".tsv", "tab"},
    {Format::json, Kind::json, "json", ".json", ""},
    {Format::gltf, Kind::mesh, "gltf", ".gltf", ""},
    {Format::glb, Kind::mesh, "glb", ".glb", ""},
    {Format::dae, Kind::mesh, "dae", ".dae", "collada"},
    {Format::fbx, Kind::mesh, "fbx", ".fbx", ""},
    {Format::threeds, Kind::mesh, "3ds", ".3ds", ""},
    {Format::xfile, Kind::mesh, "x", ".x", ""},
    {Format::lwo, Kind::mesh, "lwo", ".lwo", "lightwave"},
};

const FormatRow& row(Format f) {
  for (const FormatRow& r : kFormats)
    if (r.format == f) return r;
  return kFormats[0];  // unreachable: every enumerator has a row
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

bool name_matches(const FormatRow& r, const std::string& name) {
  if (name == r.name || name == r.extension + 1) return true;
  std::string_view aliases = r.aliases;
  while (!aliases.empty()) {
    std::size_t sp = aliases.find(' ');
    if (aliases.substr(0, sp) == name) return true;
    if (sp == std::string_view::npos) break;
    aliases.remove_prefix(sp + 1);
  }
  return false;
}

// Skips whitespace and lines starting with '#'.
std::string_view skip_blank_and_comments(std::string_view s) {
  for (;;) {
    std::size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    s.remove_prefix(i);
    if (!s.empty() && s.front() == '#') {
      std::size_t nl = s.find('\n');
      if (nl == std::string_view::npos) return {};
      s.remove_prefix(nl + 1);
      continue;
    }
    return s;
  }
}

std::string_view first_line(std::string_view s) {
  std::size_t nl = s.find('\n');
  std::string_view line = s.substr(0, nl);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::string_view first_token(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(0, i);
}

bool is_binary_stl(std::string_view b) {
  if (b.size() < 84) return false;
  std::uint32_t n;
  std::memcpy(&n, b.data() + 80, 4);  // little-endian on every platform fest builds for
  return 84ull + 50ull * n == b.size();
}

std::uint32_t le32(std::string_view b, std::size_t off) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + off, 4);  // little-endian on every platform fest builds for
  return v;
}
std::uint32_t be32(std::string_view b, std::size_t off) { return __builtin_bswap32(le32(b, off)); }
std::int16_t i16_in(std::string_view b, std::size_t off, bool big) {
  std::uint16_t v;
  std::memcpy(&v, b.data() + off, 2);
  return static_cast<std::int16_t>(big ? __builtin_bswap16(v) : v);
}

// NIfTI-1 (sizeof_hdr 348, magic "n+1" or "ni1" at 344), NIfTI-2 (540, "n+2"/"ni2" at 4)
// and Analyze 7.5 (348 without a magic: recognised by a sane dim[0] and datatype code).
std::optional<Format> nifti_family(std::string_view b) {
  if (b.size() < 348) return std::nullopt;
  const bool le348 = le32(b, 0) == 348, be348 = be32(b, 0) == 348;
  if (le348 || be348) {
    if (std::memcmp(b.data() + 344, "n+1\0", 4) == 0) return Format::nifti;
    if (std::memcmp(b.data() + 344, "ni1\0", 4) == 0) return Format::nifti_pair;
    const int ndim = i16_in(b, 40, be348 && !le348), code = i16_in(b, 70, be348 && !le348);
    static const int codes[] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 768, 1024, 1280, 1536, 1792, 2048, 2304};
    const bool known = std::find(std::begin(codes), std::end(codes), code) != std::end(codes);
    if (ndim >= 1 && ndim <= 7 && known) return Format::analyze;
    if (b[344] == 'n') return Format::nifti;  // a damaged NIfTI magic: the reader names it
    return std::nullopt;
  }
  if (b.size() >= 540 && (le32(b, 0) == 540 || be32(b, 0) == 540)) {
    // "n+2\0" then \r\n\032\n (or zeros, as nifti_clib 3.0 writes): the reader checks the rest.
    if (std::memcmp(b.data() + 4, "n+2\0", 4) == 0) return Format::nifti2;
    if (std::memcmp(b.data() + 4, "ni2\0", 4) == 0) return Format::nifti_pair;
  }
  return std::nullopt;
}

// FreeSurfer MGH: no magic, so a big-endian version 1, four positive sizes, a known
// type code and a file long enough for the voxels the header declares.
bool is_mgh(std::string_view b) {
  if (b.size() < 284 || be32(b, 0) != 1) return false;
  std::uint64_t count = 1;
  for (int i = 0; i < 4; ++i) {
    const auto d = static_cast<std::int32_t>(be32(b, 4 + 4 * i));
    if (d <= 0) return false;
    count *= static_cast<std::uint64_t>(d);
    if (count > (1ull << 40)) return false;
  }
  std::uint64_t bytes_per_voxel = 0;
  switch (be32(b, 20)) {
    case 0: bytes_per_voxel = 1; break;                   // MRI_UCHAR
    case 4: case 10: bytes_per_voxel = 2; break;          // MRI_SHORT, MRI_USHRT
    case 1: case 2: case 3: bytes_per_voxel = 4; break;   // MRI_INT, MRI_LONG, MRI_FLOAT
    case 5: case 6: bytes_per_voxel = 0; break;           // bitmap, tensor: the reader names them
    default: return false;
  }
  return b.size() - 284 >= count * bytes_per_voxel;
}

// OFF variants: OFF, COFF, NOFF, CNOFF, STOFF, 4OFF, nOFF, ... (the keyword ends in OFF).
bool is_off(std::string_view text) {
  std::string_view tok = first_token(skip_blank_and_comments(text));
  return tok.size() >= 3 && tok.size() <= 8 && tok.substr(tok.size() - 3) == "OFF";
}

// OBJ has no magic: accept text whose first statement is an OBJ keyword.
bool is_obj(std::string_view text) {
  std::string_view tok = first_token(skip_blank_and_comments(text));
  static const char* keywords[] = {"v", "vt", "vn", "vp", "f", "o", "g", "s", "l", "p", "mtllib", "usemtl"};
  for (const char* k : keywords)
    if (tok == k) return true;
  return false;
}

// MetaImage headers are "Key = value" lines in any order; accept the keys that can
// open one (ITK writes ObjectType first, other writers start with a Comment).
bool is_metaimage(std::string_view b) {
  static const char* keys[] = {"ObjectType", "NDims", "Comment", "ObjectSubType", "TransformType", "DimSize"};
  for (const char* k : keys) {
    if (!starts_with(b, k)) continue;
    std::string_view rest = b.substr(std::strlen(k));
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
    if (!rest.empty() && rest.front() == '=') return true;
  }
  return false;
}

Format detect_xml(std::string_view b, const std::string& where) {
  std::size_t vtk = b.substr(0, 4096).find("<VTKFile");
  if (vtk == std::string_view::npos)
    throw bad_input("{}", with_location("XML input is not a VTK file (no <VTKFile> element)", where));
  std::string_view tag = b.substr(vtk, b.substr(vtk).find('>'));
  if (tag.find("\"UnstructuredGrid\"") != std::string_view::npos) return Format::vtu;
  if (tag.find("\"ImageData\"") != std::string_view::npos) return Format::vti;
  if (tag.find("\"PolyData\"") != std::string_view::npos) return Format::vtp;
  if (tag.find("\"StructuredGrid\"") != std::string_view::npos) return Format::vts;
  throw bad_input("{}", with_location("unsupported VTK XML dataset type (fest reads UnstructuredGrid, "
                                      "ImageData, PolyData and StructuredGrid)", where));
}

// CSV/TSV: a header line of names, then lines of numbers; decided by the delimiter
// the header uses. Binary data (a NUL byte early on) is never a table.
bool looks_like_table(std::string_view b, Format& out) {
  std::string_view head = b.substr(0, 4096);
  if (head.find('\0') != std::string_view::npos) return false;
  std::string_view line = first_line(skip_blank_and_comments(b));
  if (line.empty()) return false;
  for (unsigned char c : line)
    if (c < 0x09 || (c > 0x0d && c < 0x20)) return false;
  if (line.find('\t') != std::string_view::npos) {
    out = Format::tsv;
    return true;
  }
  if (line.find(',') != std::string_view::npos) {
    out = Format::csv;
    return true;
  }
  return false;
}

}  // namespace

Kind kind_of(Format f) noexcept { return row(f).kind; }

const char* kind_name(Kind k) noexcept {
  switch (k) {
    case Kind::mesh: return "mesh";
    case Kind::image: return "image";
    case Kind::volume: return "volume";
    case Kind::dataset: return "dataset";
    case Kind::table: return "table";
    case Kind::json: return "json";
  }
  return "unknown";
}

const char* format_name(Format f) noexcept { return row(f).name; }

bool read_only_scene_format(Format f) noexcept { return f >= Format::gltf && f <= Format::lwo; }

namespace {

// The scene formats assimp reads, by their signatures: GLB "glTF" version 2; FBX's
// binary magic or its ascii header comment; DirectX "xof 03"; LightWave's IFF FORM;
// 3DS's main chunk 0x4D4D whose length is the file's, followed by a version (0x0002) or
// editor (0x3D3D) chunk. Text glTF and COLLADA are recognised among JSON and XML.
std::optional<Format> scene_signature(std::string_view b) {
  if (b.size() >= 12 && starts_with(b, "glTF") && le32(b, 4) == 2) return Format::glb;
  if (starts_with(b, std::string_view("Kaydara FBX Binary  \0", 21)) || starts_with(b, "; FBX ")) return Format::fbx;
  if (starts_with(b, "xof 03")) return Format::xfile;
  if (b.size() >= 12 && starts_with(b, "FORM") &&
      (b.substr(8, 4) == "LWO2" || b.substr(8, 4) == "LWOB" || b.substr(8, 4) == "LWLO"))
    return Format::lwo;
  if (b.size() >= 16 && static_cast<unsigned char>(b[0]) == 0x4D && static_cast<unsigned char>(b[1]) == 0x4D &&
      le32(b, 2) == b.size()) {
    const unsigned next = static_cast<unsigned char>(b[6]) | (static_cast<unsigned char>(b[7]) << 8);
    if (next == 0x0002 || next == 0x3D3D) return Format::threeds;
  }
  return std::nullopt;
}

// A JSON document with glTF's required "asset" object and geometry ("meshes").
bool is_gltf_json(std::string_view text) {
  return text.find("\"asset\"") != std::string_view::npos && text.find("\"meshes\"") != std::string_view::npos;
}

}  // namespace
const char* format_extension(Format f) noexcept { return row(f).extension; }

Format detect_format(std::string_view b, const std::string& where) {
  if (b.empty()) throw bad_input("{}", with_location("empty input", where));

  // Binary signatures first: they are unambiguous. The scene signatures lead: a 3DS file
  // whose length has 0x2A00 as its low 16 bits starts "MM\0*", TIFF's big-endian magic,
  // and its chunk-length and version checks are the stronger evidence (a TIFF would need
  // its size in its IFD offset's high bytes and 0x0200 or 0x3D3D in the low ones).
  if (const std::optional<Format> scene = scene_signature(b)) return *scene;
  if (starts_with(b, "\x89PNG\r\n\x1a\n")) return Format::png;
  if (starts_with(b, std::string_view("\x76\x2f\x31\x01", 4))) return Format::exr;
  if (starts_with(b, std::string_view("II*\0", 4)) || starts_with(b, std::string_view("MM\0*", 4)))
    return Format::tiff;
  if (starts_with(b, "\xff\xd8\xff")) return Format::jpeg;
  if (starts_with(b, "DRACO")) return Format::drc;
  if (starts_with(b, "NRRD000")) return Format::nrrd;
  if (const std::optional<Format> nifti = nifti_family(b); nifti && *nifti != Format::analyze) return *nifti;
  if (starts_with(b, "CDF\x01") || starts_with(b, "CDF\x02"))
    throw bad_input("{}", with_location("netCDF data (a MINC-1 volume?) is not supported; convert it to NIfTI first "
                                        "(mnc2nii, or nibabel)", where));
  if (starts_with(b, "\x89HDF\r\n\x1a\n"))
    throw bad_input("{}", with_location("HDF5 data (a MINC-2 volume?) is not supported; convert it to NIfTI first "
                                        "(mnc2nii, or nibabel)", where));
  if (starts_with(b, "\x1f\x8b"))
    throw bad_input("{}", with_location("gzip data inside gzip data is not supported", where));
  if (starts_with(b, "ply\n") || starts_with(b, "ply\r\n")) return Format::ply;
  if (b.size() >= 3 && b[0] == 'P' && std::isspace(static_cast<unsigned char>(b[2]))) {
    switch (b[1]) {
      case '2': case '5': return Format::pgm;
      case '3': case '6': return Format::ppm;
      case '7': return Format::pam;
      case 'F': case 'f': return Format::pfm;
      default: break;
    }
  }
  if (starts_with(b, "# vtk DataFile Version")) return Format::vtk;
  // Binary STL: an 80-byte header (which may itself begin with "solid") and a count that
  // accounts for the file size exactly. Checked before ascii STL for that reason.
  if (is_binary_stl(b)) return Format::stl;
  // Formats without a magic number, recognised by a consistent binary header.
  if (const std::optional<Format> nifti = nifti_family(b)) return *nifti;  // Analyze 7.5
  if (is_mgh(b)) return Format::mgh;

  std::string_view text = skip_blank_and_comments(b);
  if (starts_with(b, "solid") && b.substr(0, 1024).find("facet") != std::string_view::npos) return Format::stl;
  if (starts_with(b, "solid") && b.size() < 1024 && b.find("endsolid") != std::string_view::npos)
    return Format::stl;  // an empty ascii STL: still an STL (the reader reports it)
  if ((starts_with(text, "<?xml") || starts_with(text, "<COLLADA")) &&
      text.substr(0, 4096).find("<COLLADA") != std::string_view::npos)
    return Format::dae;
  if (starts_with(text, "<?xml") || starts_with(text, "<VTKFile")) return detect_xml(text, where);
  if (is_metaimage(b)) return Format::mha;
  if (!text.empty() && text.front() == '{' && is_gltf_json(text)) return Format::gltf;
  if (!text.empty() && (text.front() == '{' || text.front() == '[')) return Format::json;
  if (is_off(b)) return Format::off;
  if (is_obj(b)) return Format::obj;
  Format table;
  if (looks_like_table(b, table)) return table;
  throw bad_input("{}", with_location("unrecognised input format (starts with \"" + fest::quoted_bytes(b, 16) + "\")", where));
}

OutputFormat output_format_from_name(std::string_view name_in) {
  std::string name = lower(name_in);
  OutputFormat out{Format::ply, false};
  if (name.size() > 3 && name.compare(name.size() - 3, 3, ".gz") == 0) {
    out.gzip = true;
    name.resize(name.size() - 3);
  } else if (name == "gz") {
    throw usage_error("'gz' names a compression, not a format: say e.g. nii.gz");
  }
  if (!name.empty() && name.front() == '.') name.erase(0, 1);
  if (name == "mgz") return OutputFormat{Format::mgh, true};  // FreeSurfer's gzip-compressed MGH
  for (const FormatRow& r : kFormats) {
    if (name_matches(r, name)) {
      if (read_only_scene_format(r.format))
        throw usage_error("fest reads {} (through assimp) but does not write it", r.name);
      out.format = r.format;
      return out;
    }
  }
  throw usage_error("unknown output format '{}'", std::string(name_in));
}

OutputFormat output_format_from_path(std::string_view path) {
  std::string_view base = path.substr(path.find_last_of('/') == std::string_view::npos ? 0 : path.find_last_of('/') + 1);
  std::string lowered = lower(base);
  bool gz = false;
  if (lowered.size() > 3 && lowered.compare(lowered.size() - 3, 3, ".gz") == 0) {
    gz = true;
    lowered.resize(lowered.size() - 3);
  }
  std::size_t dot = lowered.find_last_of('.');
  if (dot == std::string::npos || dot == 0)
    throw usage_error("cannot tell the output format from '{}': give it an extension or --to", std::string(path));
  std::string ext = lowered.substr(dot + 1);
  if (ext == "mgz" && !gz) return OutputFormat{Format::mgh, true};
  for (const FormatRow& r : kFormats) {
    if (name_matches(r, ext)) {
      if (read_only_scene_format(r.format))
        throw usage_error("fest reads {} (through assimp) but does not write it ({})", r.name, std::string(path));
      return OutputFormat{r.format, gz};
    }
  }
  throw usage_error("unknown output extension '.{}' ({}); use --to to name the format", ext, std::string(path));
}

}  // namespace fest::formats
