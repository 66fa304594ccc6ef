#include "formats/facemodel/mmb.hpp"
#include "core/json_value.hpp"
#include "core/quote.hpp"

#include <cstdint>
#include <cstring>
#include <memory>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/face_model_basis.hpp"
#include "formats/table/table_io.hpp"

namespace fest::formats {

namespace {

static_assert(sizeof(float) == 4 && sizeof(double) == 8, "IEEE floats expected");

bool little_endian() {
  const std::uint16_t one = 1;
  std::uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

std::size_t dtype_size(const std::string& t) {
  if (t == "f32" || t == "u32") return 4;
  if (t == "f64") return 8;
  return 0;
}

struct ArrayRef {
  std::string dtype;
  std::vector<std::uint64_t> shape;
  const unsigned char* data = nullptr;
  std::uint64_t count = 0;
};

// Validates the header's array table against the file size; returns the arrays by name.
std::map<std::string, ArrayRef> array_table(const nlohmann::json& header, const unsigned char* base, std::uint64_t size) {
  std::map<std::string, ArrayRef> arrays;
  if (!header.contains("arrays") || !header["arrays"].is_array()) throw bad_input("mmb header: no 'arrays' list");
  for (const auto& a : header["arrays"]) {
    if (!a.is_object() || !a.contains("name") || !a["name"].is_string() || !a.contains("dtype") || !a["dtype"].is_string() ||
        !a.contains("shape") || !a["shape"].is_array() || !a.contains("offset") || !a["offset"].is_number_unsigned())
      throw bad_input("mmb header: an array entry lacks name, dtype, shape or offset");
    ArrayRef ref;
    const std::string name = a["name"].get<std::string>();
    ref.dtype = a["dtype"].get<std::string>();
    const std::size_t es = dtype_size(ref.dtype);
    if (es == 0) throw bad_input("mmb array '{}': unknown dtype '{}'", fest::quoted_bytes(name), fest::quoted_bytes(ref.dtype));
    ref.count = 1;
    for (const auto& d : a["shape"]) {
      if (!d.is_number_unsigned()) throw bad_input("mmb array '{}': shape must hold non-negative integers", fest::quoted_bytes(name));
      const std::uint64_t v = d.get<std::uint64_t>();
      if (v != 0 && ref.count > (std::uint64_t{1} << 40) / v) throw bad_input("mmb array '{}': shape too large", fest::quoted_bytes(name));
      ref.count *= v;
      ref.shape.push_back(v);
    }
    const std::uint64_t offset = fest::json_integer<std::uint64_t>(a["offset"]);
    if (offset % es != 0) throw bad_input("mmb array '{}': offset {} not aligned to its element size", fest::quoted_bytes(name), offset);
    if (offset > size || ref.count * es > size - offset)
      throw bad_input("mmb array '{}': bytes {}..{} lie beyond the end of the file ({} bytes): truncated", fest::quoted_bytes(name), offset,
                      offset + ref.count * es, size);
    ref.data = base + offset;
    arrays[name] = ref;
  }
  return arrays;
}

std::vector<double> to_doubles(const ArrayRef& a, const char* what) {
  std::vector<double> out(a.count);
  if (a.dtype == "f64")
    std::memcpy(out.data(), a.data, a.count * 8);
  else if (a.dtype == "f32")
    for (std::uint64_t i = 0; i < a.count; ++i) {
      float v;
      std::memcpy(&v, a.data + 4 * i, 4);
      out[i] = v;
    }
  else
    throw bad_input("mmb array '{}' must be f32 or f64", what);
  return out;
}

std::vector<std::uint32_t> to_u32(const ArrayRef& a, const char* what) {
  if (a.dtype != "u32") throw bad_input("mmb array '{}' must be u32", what);
  std::vector<std::uint32_t> out(a.count);
  std::memcpy(out.data(), a.data, a.count * 4);
  return out;
}

const ArrayRef& need(const std::map<std::string, ArrayRef>& arrays, const char* name) {
  auto it = arrays.find(name);
  if (it == arrays.end()) throw bad_input("mmb: array '{}' missing", fest::quoted_bytes(name));
  return it->second;
}

// Builds the model from a validated mapping; `keep` owns the bytes.
face::Model decode(const unsigned char* base, std::uint64_t size, std::shared_ptr<const void> keep,
                      const MmbReadOptions& options, std::string* warnings) {
  if (!little_endian()) throw bad_input("mmb files are little endian; this machine is not");
  if (size < 16) throw bad_input("mmb: file of {} bytes is shorter than the 16-byte preamble: truncated", size);
  if (std::memcmp(base, mmb_magic, 8) != 0) throw bad_input("not a morphable model file: wrong magic (expected MORPHMB1)");
  std::uint64_t H;
  std::memcpy(&H, base + 8, 8);
  if (H > size - 16) throw bad_input("mmb: header length {} exceeds the file ({} bytes): truncated", H, size);
  nlohmann::json header;
  try {
    header = read_json(std::string_view(reinterpret_cast<const char*>(base + 16), H));
  } catch (const Error& e) {
    throw bad_input("mmb header (file offset 16): {}", e.what());
  }
  if (!header.is_object()) throw bad_input("mmb header is not a JSON object");
  auto number = [&](const char* key) -> std::uint64_t {
    if (!header.contains(key) || !header[key].is_number_unsigned()) throw bad_input("mmb header: '{}' missing or not a count", key);
    return header[key].get<std::uint64_t>();
  };
  if (json_string_or(header, "format", "") != "mmb") throw bad_input("mmb header: format is not \"mmb\"");
  if (number("version") != 1) throw bad_input("mmb header: version {} not supported (1 is)", number("version"));
  if (json_string_or(header, "sigma_kind", "") != "stddev")
    throw bad_input("mmb header: sigma_kind must be \"stddev\" (convert variances with facefit convert)");

  face::Model m;
  m.dims = static_cast<int>(number("dims"));
  if (m.dims != 2 && m.dims != 3) throw bad_input("mmb header: dims {} (2 or 3)", m.dims);
  m.points = number("points");
  m.components = number("components");
  if (m.points > (std::uint64_t{1} << 32)) throw bad_input("mmb header: too many points");
  m.units = json_string_or(header, "units", "mm");
  m.source = json_string_or(header, "source", "");
  m.license = json_string_or(header, "license", "");
  if (header.contains("training_examples") && header["training_examples"].is_number_unsigned())
    m.training_examples = header["training_examples"].get<std::size_t>();
  if (header.contains("landmarks")) {
    if (!header["landmarks"].is_object()) throw bad_input("mmb header: landmarks must be an object");
    for (const auto& [name, v] : header["landmarks"].items()) {
      if (!v.is_number_unsigned()) throw bad_input("mmb header: landmark '{}' is not a vertex index", fest::quoted_bytes(name));
      m.landmarks[name] = fest::json_integer<std::uint32_t>(v);
    }
  }

  const auto arrays = array_table(header, base, size);
  const std::uint64_t n = static_cast<std::uint64_t>(m.dims) * m.points;
  const ArrayRef& mean = need(arrays, "mean");
  if (mean.count != n) throw bad_input("mmb: mean has {} values, expected dims*points = {}", mean.count, n);
  m.mean = to_doubles(mean, "mean");
  const ArrayRef& sigma = need(arrays, "sigma");
  if (sigma.count != m.components) throw bad_input("mmb: sigma has {} values, expected {}", sigma.count, m.components);
  m.sigma = to_doubles(sigma, "sigma");
  const ArrayRef& basis = need(arrays, "basis");
  if (basis.count != n * m.components) throw bad_input("mmb: basis has {} values, expected {}×{}", basis.count, n, m.components);
  if (basis.dtype == "f32")
    m.basis_type = face::Dtype::f32;
  else if (basis.dtype == "f64")
    m.basis_type = face::Dtype::f64;
  else
    throw bad_input("mmb: basis must be f32 or f64");
  m.basis = basis.data;
  m.storage = std::move(keep);
  if (auto it = arrays.find("triangles"); it != arrays.end()) {
    if (it->second.count % 3 != 0) throw bad_input("mmb: triangles array length {} is not a multiple of 3", it->second.count);
    const auto flat = to_u32(it->second, "triangles");
    m.triangles.resize(flat.size() / 3);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) m.triangles[t] = {flat[3 * t], flat[3 * t + 1], flat[3 * t + 2]};
  }
  if (header.contains("eval_mask") && header["eval_mask"].is_string()) {
    const std::string name = header["eval_mask"].get<std::string>();
    auto it = arrays.find(name);
    if (it == arrays.end()) throw bad_input("mmb: eval_mask names array '{}', which is missing", fest::quoted_bytes(name));
    m.eval_mask = to_u32(it->second, "eval_mask");
  }
  const auto fixed = face::check_model(m, options.fix_basis);
  if (warnings) {
    if (fixed.reordered) *warnings += "sigma was not descending: components reordered; ";
    if (fixed.renormalised) *warnings += "basis columns renormalised (--fix-basis); ";
  }
  return m;
}

std::string pad_to(std::string s, std::size_t multiple, char fill) {
  s.append((multiple - s.size() % multiple) % multiple, fill);
  return s;
}

// decode, with a header value of the wrong JSON type (a number where a word belongs, a
// landmark index beyond 32 bits) refused in the reader's words, not the JSON library's.
face::Model decode_header_words(const unsigned char* base, std::uint64_t size, std::shared_ptr<const void> keep,
                                const MmbReadOptions& options, std::string* warnings) {
  try {
    return decode(base, size, std::move(keep), options, warnings);
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("mmb header: {}", json_failure_words(e.what(), 0, {}));
  }
}

}  // namespace

face::Model parse_mmb(std::string bytes, const MmbReadOptions& options, std::string* warnings) {
  auto owned = std::make_shared<std::string>(std::move(bytes));
  const auto* base = reinterpret_cast<const unsigned char*>(owned->data());
  // std::string data is at least 8-byte aligned by the allocator (new), enough for f64.
  return decode_header_words(base, owned->size(), owned, options, warnings);
}

face::Model read_mmb(const std::string& path, const MmbReadOptions& options, std::string* warnings) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw io_error("cannot open model '{}': {}", path, std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw io_error("model '{}' is not a regular file", path);
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size == 0) {
    ::close(fd);
    throw bad_input("model file is empty ({})", path);
  }
  // MAP_POPULATE: every page of the basis is read by the first fit anyway; faulting them
  // in at once is several times cheaper than one fault per page.
  void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  ::close(fd);
  if (map == MAP_FAILED) throw io_error("cannot map model '{}': {}", path, std::strerror(errno));
  std::shared_ptr<const void> keep(map, [size](const void* p) { ::munmap(const_cast<void*>(p), size); });
  try {
    return decode_header_words(static_cast<const unsigned char*>(map), size, keep, options, warnings);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), path));
  }
}

std::string write_mmb(const face::Model& m) {
  if (!little_endian()) throw io_error("writing mmb files needs a little-endian machine");
  struct Blob {
    std::string name, dtype;
    std::vector<std::uint64_t> shape;
    std::string bytes;
  };
  std::vector<Blob> blobs;
  const std::uint64_t n = m.n();
  auto raw = [](const void* p, std::size_t bytes) { return std::string(static_cast<const char*>(p), bytes); };
  blobs.push_back({"mean", "f64", {n}, raw(m.mean.data(), n * 8)});
  const std::size_t es = m.basis_type == face::Dtype::f32 ? 4 : 8;
  blobs.push_back({"basis", es == 4 ? "f32" : "f64", {n, m.components}, raw(m.basis, n * m.components * es)});
  blobs.push_back({"sigma", "f64", {m.components}, raw(m.sigma.data(), m.components * 8)});
  if (!m.triangles.empty())
    blobs.push_back({"triangles", "u32", {m.triangles.size(), 3}, raw(m.triangles.data(), m.triangles.size() * 12)});
  if (!m.eval_mask.empty())
    blobs.push_back({"eval_mask", "u32", {m.eval_mask.size()}, raw(m.eval_mask.data(), m.eval_mask.size() * 4)});

  nlohmann::json header = {{"format", "mmb"},
                           {"version", 1},
                           {"dims", m.dims},
                           {"points", m.points},
                           {"components", m.components},
                           {"units", m.units},
                           {"frame", {{"x", "right"}, {"y", "up"}, {"z", "towards viewer"}}},
                           {"source", m.source},
                           {"license", m.license},
                           {"training_examples", m.training_examples},
                           {"sigma_kind", "stddev"},
                           {"basis_order", "column-major"}};
  nlohmann::json lm = nlohmann::json::object();
  for (const auto& [name, v] : m.landmarks) lm[name] = v;
  header["landmarks"] = lm;
  if (!m.eval_mask.empty()) header["eval_mask"] = "eval_mask";
  // Offsets depend on the header's length and vice versa: grow the reserved header size
  // until the text fits.
  std::uint64_t reserved = 1008;  // 16 + reserved is a multiple of 64
  std::string text;
  for (;;) {
    nlohmann::json arrays = nlohmann::json::array();
    std::uint64_t offset = 16 + reserved;
    for (const auto& b : blobs) {
      arrays.push_back({{"name", b.name}, {"dtype", b.dtype}, {"shape", b.shape}, {"offset", offset}});
      offset += (b.bytes.size() + 63) / 64 * 64;
    }
    header["arrays"] = arrays;
    text = header.dump(1);
    if (text.size() <= reserved) break;
    reserved = (text.size() + 16 + 63) / 64 * 64 - 16 + 64;
  }
  text.append(reserved - text.size(), ' ');
  std::string out(mmb_magic, 8);
  const std::uint64_t H = reserved;
  out.append(reinterpret_cast<const char*>(&H), 8);
  out += text;
  for (const auto& b : blobs) out += pad_to(b.bytes, 64, '\0');
  return out;
}

}  // namespace fest::formats
