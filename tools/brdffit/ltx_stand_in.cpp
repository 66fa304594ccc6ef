#include "ltx_stand_in.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.hpp"

namespace brdffit_tool {

namespace {

using fest::bad_input;

constexpr char kMagic[8] = {'L', 'U', 'M', 'I', 'T', 'E', 'X', '1'};
constexpr std::size_t kLumitexelBytes = 48, kSampleBytes = 42;

template <typename T>
void put(std::string& out, T v) {  // little-endian hosts only (x86-64, arm64)
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}
template <typename T>
T get(const char*& p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  p += sizeof(T);
  return v;
}

std::uint64_t count_of(const nlohmann::json& h, const char* name) {
  const nlohmann::json* j = nullptr;
  if (h.contains("counts") && h["counts"].contains(name)) j = &h["counts"][name];
  else if (h.contains(name)) j = &h[name];
  if (!j || !j->is_number_unsigned()) throw bad_input(".ltx header: no count of {}", name);
  return j->get<std::uint64_t>();
}

}  // namespace

fest::brdffit::LumitexelSet read_ltx_stand_in(std::string_view bytes, nlohmann::json* header) {
  if (bytes.size() < 12 || std::memcmp(bytes.data(), kMagic, 8) != 0) throw bad_input("not a .ltx file: no LUMITEX1 magic (offset 0)");
  const char* p = bytes.data() + 8;
  const auto hlen = get<std::uint32_t>(p);
  if (bytes.size() - 12 < hlen) throw bad_input("truncated .ltx header (offset 8)");
  nlohmann::json h = nlohmann::json::parse(bytes.substr(12, hlen), nullptr, false);
  if (h.is_discarded() || !h.is_object()) throw bad_input(".ltx header is not a JSON object (offset 12)");
  const std::uint64_t n = count_of(h, "lumitexels"), m = count_of(h, "samples");
  const std::size_t body = bytes.size() - 12 - hlen;
  if (n > body / kLumitexelBytes || m > body / kSampleBytes || n * kLumitexelBytes + m * kSampleBytes != body)
    throw bad_input("truncated .ltx arrays: {} lumitexels and {} samples announced, {} bytes at offset {}", n, m, body, 12 + hlen);
  fest::brdffit::LumitexelSet set;
  if (h.contains("mesh_sha256") && h["mesh_sha256"].is_string()) set.mesh_sha256 = h["mesh_sha256"];
  if (h.contains("images") && h["images"].is_array())
    for (const auto& im : h["images"]) set.images.push_back(im.is_string() ? im.get<std::string>() : im.dump());
  p = bytes.data() + 12 + hlen;
  set.lumitexels.resize(n);
  for (auto& l : set.lumitexels) {
    for (int k = 0; k < 3; ++k) l.p[k] = get<float>(p);
    for (int k = 0; k < 3; ++k) l.n[k] = get<float>(p);
    l.triangle = get<std::uint32_t>(p);
    l.home_image = get<std::uint16_t>(p);
    for (int k = 0; k < 2; ++k) l.home_pixel[k] = get<float>(p);
    l.first_sample = get<std::uint64_t>(p);
    l.count = get<std::uint16_t>(p);
    if (l.first_sample > m || l.count > m - l.first_sample) throw bad_input(".ltx lumitexel samples out of range");
    if (!l.n.allFinite() || !(l.n.norm() > 0)) throw bad_input(".ltx lumitexel normal is not a finite non-zero vector");
  }
  set.samples.resize(m);
  for (auto& s : set.samples) {
    s.image = get<std::uint16_t>(p);
    for (int k = 0; k < 3; ++k) s.u_world[k] = get<float>(p);
    for (int k = 0; k < 3; ++k) s.v_world[k] = get<float>(p);
    for (int k = 0; k < 3; ++k) s.r[k] = get<float>(p);
    s.weight = get<float>(p);
  }
  if (header) *header = std::move(h);
  return set;
}

std::string write_ltx_stand_in(const fest::brdffit::LumitexelSet& set, nlohmann::json h) {
  h["format"] = "ltx";
  h["mesh_sha256"] = set.mesh_sha256;
  h["images"] = set.images;
  h["counts"] = {{"lumitexels", set.lumitexels.size()}, {"samples", set.samples.size()}};
  const std::string text = h.dump();
  std::string out(kMagic, 8);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(text.size()));
  out += text;
  for (const auto& l : set.lumitexels) {
    for (int k = 0; k < 3; ++k) put<float>(out, l.p[k]);
    for (int k = 0; k < 3; ++k) put<float>(out, l.n[k]);
    put<std::uint32_t>(out, l.triangle);
    put<std::uint16_t>(out, l.home_image);
    for (int k = 0; k < 2; ++k) put<float>(out, l.home_pixel[k]);
    put<std::uint64_t>(out, l.first_sample);
    put<std::uint16_t>(out, l.count);
  }
  for (const auto& s : set.samples) {
    put<std::uint16_t>(out, s.image);
    for (int k = 0; k < 3; ++k) put<float>(out, s.u_world[k]);
    for (int k = 0; k < 3; ++k) put<float>(out, s.v_world[k]);
    for (int k = 0; k < 3; ++k) put<float>(out, s.r[k]);
    put<float>(out, s.weight);
  }
  return out;
}

}  // namespace brdffit_tool
