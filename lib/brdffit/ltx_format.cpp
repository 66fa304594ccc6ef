#include "brdffit/ltx_format.hpp"
#include "core/json_value.hpp"
#include "core/quote.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.hpp"

namespace fest::brdffit {
namespace {

// Little-endian packing independent of the host's byte order and struct padding.
class Writer {
 public:
  explicit Writer(std::vector<std::uint8_t>& out) : out_(out) {}
  void u16(std::uint16_t v) { le(v, 2); }
  void u32(std::uint32_t v) { le(v, 4); }
  void u64(std::uint64_t v) { le(v, 8); }
  void f32(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    le(bits, 4);
  }
  void vec3(const Eigen::Vector3f& v) {
    for (int k = 0; k < 3; ++k) f32(v[k]);
  }
  // One record field by its type (lumitexel_fields, sample_fields).
  void field(std::uint16_t v) { u16(v); }
  void field(std::uint32_t v) { u32(v); }
  void field(std::uint64_t v) { u64(v); }
  void field(float v) { f32(v); }
  void field(const Eigen::Vector3f& v) { vec3(v); }
  void field(const Eigen::Vector2f& v) {
    f32(v.x());
    f32(v.y());
  }

 private:
  void le(std::uint64_t v, int n) {
    for (int k = 0; k < n; ++k) out_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  std::vector<std::uint8_t>& out_;
};

class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& in, std::size_t pos) : in_(in), pos_(pos) {}
  std::size_t pos() const { return pos_; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(le(4)); }
  std::uint64_t u64() { return le(8); }
  float f32() {
    const auto bits = static_cast<std::uint32_t>(le(4));
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  }
  Eigen::Vector3f vec3() {
    Eigen::Vector3f v;
    for (int k = 0; k < 3; ++k) v[k] = f32();
    return v;
  }
  // One record field by its type (lumitexel_fields, sample_fields).
  void field(std::uint16_t& v) { v = u16(); }
  void field(std::uint32_t& v) { v = u32(); }
  void field(std::uint64_t& v) { v = u64(); }
  void field(float& v) { v = f32(); }
  void field(Eigen::Vector3f& v) { v = vec3(); }
  void field(Eigen::Vector2f& v) {
    v.x() = f32();
    v.y() = f32();
  }

 private:
  std::uint64_t le(int n) {
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k) v |= static_cast<std::uint64_t>(in_[pos_ + static_cast<std::size_t>(k)]) << (8 * k);
    pos_ += static_cast<std::size_t>(n);
    return v;
  }
  const std::vector<std::uint8_t>& in_;
  std::size_t pos_;
};

// The two record layouts (the header's lumitexel_layout and sample_layout, below), one
// list of fields each for writing (Writer, const records) and reading (Reader); the
// fields go in order (a comma fold runs left to right).
template <typename Io, typename... Field>
void fields(Io& io, Field&... f) {
  (io.field(f), ...);
}
template <typename Io, typename L>
void lumitexel_fields(Io& io, L& l) {
  fields(io, l.p, l.n, l.triangle, l.home_image, l.home_pixel, l.first_sample, l.count);
}
template <typename Io, typename S>
void sample_fields(Io& io, S& s) {
  fields(io, s.image, s.u_world, s.v_world, s.r, s.weight);
}

nlohmann::json layouts() {
  return {{"lumitexel_layout",
           {"p:3xf32", "n:3xf32", "triangle:u32", "home_image:u16", "home_pixel:2xf32", "first_sample:u64",
            "count:u16"}},
          {"sample_layout", {"image:u16", "u_world:3xf32", "v_world:3xf32", "r:3xf32", "weight:f32"}}};
}

void check_records(const LumitexelSet& set) {
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i) {
    const Lumitexel& l = set.lumitexels[i];
    if (l.first_sample > set.samples.size() || l.count > set.samples.size() - l.first_sample)
      throw bad_input("lumitexel {}: samples [{}, {}) outside the {} samples", i, l.first_sample,
                      l.first_sample + l.count, set.samples.size());
    if (!set.images.empty() && l.home_image >= set.images.size())
      throw bad_input("lumitexel {}: home image {} but {} images", i, l.home_image, set.images.size());
  }
  for (std::size_t s = 0; s < set.samples.size(); ++s)
    if (set.samples[s].image >= set.images.size())
      throw bad_input("sample {}: image {} but {} images", s, set.samples[s].image, set.images.size());
}

}  // namespace

std::vector<std::uint8_t> encode_ltx(const LumitexelSet& set, const nlohmann::json& header) {
  check_records(set);
  nlohmann::json h = header.is_object() ? header : nlohmann::json::object();
  h["format"] = "ltx";
  h["version"] = 1;
  h["mesh_sha256"] = set.mesh_sha256;
  h["images"] = set.images;
  h["lumitexels"] = set.lumitexels.size();
  h["samples"] = set.samples.size();
  h.update(layouts());
  const std::string text = h.dump();
  std::vector<std::uint8_t> out;
  out.reserve(12 + text.size() + set.lumitexels.size() * ltx_lumitexel_bytes + set.samples.size() * ltx_sample_bytes);
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<std::uint8_t>(ltx_magic[k]));
  Writer w(out);
  w.u32(static_cast<std::uint32_t>(text.size()));
  for (char ch : text) out.push_back(static_cast<std::uint8_t>(ch));
  for (const Lumitexel& l : set.lumitexels) lumitexel_fields(w, l);
  for (const Sample& s : set.samples) sample_fields(w, s);
  return out;
}

LumitexelSet decode_ltx(const std::vector<std::uint8_t>& bytes, nlohmann::json* header_out) {
  if (bytes.size() < 12 || std::memcmp(bytes.data(), ltx_magic, 8) != 0)
    throw bad_input("not a lumitexel file: the first 8 bytes are not LUMITEX1 (offset 0)");
  const std::uint32_t hlen = Reader(bytes, 8).u32();
  if (hlen > bytes.size() - 12) throw bad_input("header of {} bytes runs past the end of the file (offset 8)", hlen);
  nlohmann::json h;
  try {
    h = nlohmann::json::parse(bytes.begin() + 12, bytes.begin() + 12 + hlen);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte counts from the header's first byte, which is file offset 12.
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()) + 12, hlen);
    throw bad_input("header: {} (offset {})", json_failure_words(e.what(), e.byte, text), 12 + (e.byte > 0 ? e.byte - 1 : 0));
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("header: {} (offset 12)", json_failure_words(e.what(), 0, {}));
  }
  LumitexelSet set;
  std::uint64_t n = 0, m = 0;
  const char* field = "";  // the header field being read, for the message
  try {
    if (!h.is_object()) throw bad_input("the header is not a JSON object (offset 12)");
    if (h.value("format", "") != "ltx") throw bad_input("the header's \"format\" is not \"ltx\" (offset 12)");
    if (const auto version = json_integer_or<std::int64_t>(h, "version", 0); version != 1)
      throw bad_input("unsupported .ltx version {} (offset 12)", version);
    field = "mesh_sha256";
    set.mesh_sha256 = h.at(field).get<std::string>();
    field = "images";
    set.images = h.at(field).get<std::vector<std::string>>();
    field = "lumitexels";
    n = json_integer<std::uint64_t>(h.at(field));
    field = "samples";
    m = json_integer<std::uint64_t>(h.at(field));
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("header field \"{}\": {} (offset 12)", field, json_failure_words(e.what(), 0, {}));
  }
  const std::size_t start = 12 + hlen;
  const std::size_t avail = bytes.size() - start;
  // Overflow-safe size check before any allocation: counts must fit the bytes present.
  if (n > avail / ltx_lumitexel_bytes || m > (avail - n * ltx_lumitexel_bytes) / ltx_sample_bytes)
    throw bad_input("truncated: the header announces {} lumitexels and {} samples, {} bytes follow it (offset {})", n, m,
                    avail, start);
  const std::size_t expected = n * ltx_lumitexel_bytes + m * ltx_sample_bytes;
  if (avail != expected)
    throw bad_input("{} bytes after the records (offset {})", avail - expected, start + expected);
  Reader r(bytes, start);
  set.lumitexels.resize(n);
  for (Lumitexel& l : set.lumitexels) lumitexel_fields(r, l);
  set.samples.resize(m);
  for (Sample& s : set.samples) sample_fields(r, s);
  try {
    check_records(set);
  } catch (const Error& e) {
    throw bad_input("{} (offset {})", e.what(), start);
  }
  if (header_out) *header_out = std::move(h);
  return set;
}

}  // namespace fest::brdffit
