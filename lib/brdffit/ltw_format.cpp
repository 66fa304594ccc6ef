#include "brdffit/ltw_format.hpp"
#include "core/json_value.hpp"
#include "core/quote.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "brdffit/brdf_json.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

constexpr char kMagic[8] = {'L', 'U', 'M', 'I', 'W', 'G', 'T', '1'};

void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>(v >> 8));
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
void put_f32(std::string& out, float f) {
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(out, v);
}
std::uint32_t get_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 | static_cast<std::uint32_t>(p[2]) << 16 |
         static_cast<std::uint32_t>(p[3]) << 24;
}
float get_f32(const unsigned char* p) {
  const std::uint32_t v = get_u32(p);
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}

}  // namespace

std::string encode_ltw(const Projection& p, const nlohmann::json& extra) {
  nlohmann::json h = extra.is_object() ? extra : nlohmann::json::object();
  h["format"] = "ltw";
  h["version"] = 1;
  h["model"] = model_to_json(p.basis.model);
  h["lumitexels"] = p.cluster.size();
  h["basis_size"] = p.basis_size;
  h["weights"] = p.mode == WeightMode::rgb ? "rgb" : "scalar";
  nlohmann::json basis = nlohmann::json::array();
  for (const Eigen::VectorXd& b : p.basis.brdfs)
    basis.push_back({{"params", std::vector<double>(b.data(), b.data() + b.size())},
                     {"brdf", brdf_to_json(to_brdf(p.basis.model, b))}});
  h["basis"] = basis;
  nlohmann::json clusters = nlohmann::json::array();
  for (const auto& list : p.basis.cluster_basis) clusters.push_back({{"basis", list}});
  h["clusters"] = clusters;
  const std::string header = h.dump();
  const auto per = static_cast<std::size_t>(p.values_per_lumitexel());
  std::string out(kMagic, 8);
  put_u32(out, static_cast<std::uint32_t>(header.size()));
  out += header;
  out.reserve(out.size() + p.cluster.size() * (2 + 4 * per));
  for (std::size_t i = 0; i < p.cluster.size(); ++i) {
    put_u16(out, p.cluster[i]);
    for (std::size_t k = 0; k < per; ++k) put_f32(out, p.weights[i * per + k]);
  }
  return out;
}

Projection decode_ltw(std::string_view bytes, nlohmann::json* header_out) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 12 || std::memcmp(b, kMagic, 8) != 0) throw bad_input("not a .ltw file: no LUMIWGT1 magic (offset 0)");
  const std::uint32_t hlen = get_u32(b + 8);
  if (bytes.size() - 12 < hlen) throw bad_input("truncated .ltw header: {} bytes announced at offset 8, {} present", hlen, bytes.size() - 12);
  nlohmann::json h = nlohmann::json::parse(bytes.substr(12, hlen), nullptr, false);
  if (h.is_discarded() || !h.is_object()) throw bad_input(".ltw header is not a JSON object (offset 12)");
  Projection p;
  try {
    p.basis.model = model_from_json(h.at("model"));
    const std::size_t n = json_integer<std::size_t>(h.at("lumitexels"));
    p.basis_size = json_integer<int>(h.at("basis_size"));
    const std::string mode = h.at("weights").get<std::string>();
    if (mode != "scalar" && mode != "rgb") throw bad_input(".ltw header: weights must be scalar or rgb");
    p.mode = mode == "rgb" ? WeightMode::rgb : WeightMode::scalar;
    if (p.basis_size < 1 || p.basis_size > 64) throw bad_input(".ltw header: basis_size {} out of 1..64", p.basis_size);
    const auto np = static_cast<Eigen::Index>(parameter_count(p.basis.model));
    for (const auto& f : h.at("basis")) {
      const std::vector<double> v = f.at("params").get<std::vector<double>>();
      if (static_cast<Eigen::Index>(v.size()) != np) throw bad_input(".ltw header: a basis BRDF has {} parameters, the model {}", v.size(), np);
      for (double x : v)
        if (!std::isfinite(x)) throw bad_input(".ltw header: a basis BRDF parameter is not finite");
      p.basis.brdfs.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), np));
    }
    for (const auto& c : h.at("clusters")) {
      std::vector<int> list = json_integers<int>(c.at("basis"));
      if (list.empty() || static_cast<int>(list.size()) > p.basis_size) throw bad_input(".ltw header: a cluster's basis list is empty or longer than basis_size");
      for (int k : list)
        if (k < 0 || static_cast<std::size_t>(k) >= p.basis.brdfs.size()) throw bad_input(".ltw header: basis index {} out of range", k);
      p.basis.cluster_basis.push_back(std::move(list));
    }
    if (p.basis.cluster_basis.empty() || p.basis.cluster_basis.size() > 65535) throw bad_input(".ltw header: no clusters");
    const auto per = static_cast<std::size_t>(p.values_per_lumitexel());
    const std::size_t record = 2 + 4 * per;
    const std::size_t body = bytes.size() - 12 - hlen;
    if (n > body / record || body != n * record)
      throw bad_input("truncated .ltw records: {} lumitexels of {} bytes need {} bytes at offset {}, {} present", n, record,
                      n * record, 12 + hlen, body);
    p.cluster.resize(n);
    p.weights.resize(n * per);
    const unsigned char* q = b + 12 + hlen;
    for (std::size_t i = 0; i < n; ++i, q += record) {
      p.cluster[i] = static_cast<std::uint16_t>(q[0] | q[1] << 8);
      if (p.cluster[i] >= p.basis.cluster_basis.size())
        throw bad_input(".ltw record {}: cluster {} out of range (offset {})", i, p.cluster[i], q - b);
      for (std::size_t k = 0; k < per; ++k) {
        p.weights[i * per + k] = get_f32(q + 2 + 4 * k);
        if (!std::isfinite(p.weights[i * per + k])) throw bad_input(".ltw record {}: weight not finite (offset {})", i, q + 2 + 4 * k - b);
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw bad_input(".ltw header: {}", json_failure_words(e.what(), 0, {}));
  }
  if (header_out) *header_out = std::move(h);
  return p;
}

}  // namespace fest::brdffit
