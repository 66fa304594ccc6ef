#include "brdffit/brdf_json.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::brdffit {

namespace {

using nlohmann::json;

json rgb(const reflectance::Rgb& v) { return json::array({v[0], v[1], v[2]}); }

const json& field(const json& j, const char* name, const char* what) {
  if (!j.is_object() || !j.contains(name)) throw bad_input("{}: missing \"{}\"", what, name);
  return j.at(name);
}

double number(const json& j, const char* what) {
  if (!j.is_number()) throw bad_input("{}: expected a number", what);
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw bad_input("{}: not a finite number", what);
  return v;
}

reflectance::Rgb rgb_from(const json& j, const char* what) {
  if (!j.is_array() || j.size() != 3) throw bad_input("{}: expected 3 numbers", what);
  return reflectance::Rgb(number(j[0], what), number(j[1], what), number(j[2], what));
}

Eigen::VectorXd vector_from(const json& j, const char* what, Eigen::Index n) {
  if (!j.is_array() || static_cast<Eigen::Index>(j.size()) != n) throw bad_input("{}: expected {} numbers", what, n);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = number(j[static_cast<std::size_t>(i)], what);
  return v;
}

}  // namespace

json brdf_to_json(const reflectance::LafortuneBrdf& b) {
  json j = {{"model", "lafortune"}, {"lobes", b.lobes.size()}, {"rho_d", rgb(b.rho_d)}};
  json cxy = json::array(), cz = json::array(), n = json::array();
  for (const auto& l : b.lobes) {
    cxy.push_back(rgb(l.cxy));
    cz.push_back(rgb(l.cz));
    n.push_back(rgb(l.n));
  }
  j["Cxy"] = cxy;
  j["Cz"] = cz;
  j["N"] = n;
  return j;
}

reflectance::LafortuneBrdf brdf_from_json(const json& j) {
  if (!j.is_object()) throw bad_input("brdf: expected a JSON object");
  if (field(j, "model", "brdf") != "lafortune") throw bad_input("brdf: model must be \"lafortune\"");
  reflectance::LafortuneBrdf b;
  b.rho_d = rgb_from(field(j, "rho_d", "brdf"), "brdf.rho_d");
  const json &cxy = field(j, "Cxy", "brdf"), &cz = field(j, "Cz", "brdf"), &n = field(j, "N", "brdf");
  if (!cxy.is_array() || !cz.is_array() || !n.is_array() || cxy.size() != cz.size() || cxy.size() != n.size() ||
      cxy.size() > 3)
    throw bad_input("brdf: Cxy, Cz and N must be lists of the same length (at most 3 lobes)");
  for (std::size_t k = 0; k < cxy.size(); ++k) {
    reflectance::LafortuneLobe l{rgb_from(cxy[k], "brdf.Cxy"), rgb_from(cz[k], "brdf.Cz"), rgb_from(n[k], "brdf.N")};
    if ((l.n.array() <= 0).any()) throw bad_input("brdf.N: exponents must be positive");
    b.lobes.push_back(l);
  }
  return b;
}

json model_to_json(const ModelSpec& s) {
  return {{"name", "lafortune"}, {"lobes", s.lobes}, {"shared_lobe", s.shared}, {"max_lobe_albedo", s.max_lobe_albedo}};
}

ModelSpec model_from_json(const json& j) {
  ModelSpec s;
  const json& lobes = field(j, "lobes", "model");
  if (!lobes.is_number_integer() || lobes.get<int>() < 1 || lobes.get<int>() > 3) throw bad_input("model.lobes must be 1, 2 or 3");
  s.lobes = lobes.get<int>();
  if (j.contains("shared_lobe")) {
    if (!j.at("shared_lobe").is_boolean()) throw bad_input("model.shared_lobe must be true or false");
    s.shared = j.at("shared_lobe").get<bool>();
  }
  if (j.contains("max_lobe_albedo")) {  // absent in files of earlier versions: the default
    const json& a = j.at("max_lobe_albedo");
    if (!a.is_number() || !(a.get<double>() >= 0)) throw bad_input("model.max_lobe_albedo must be a number >= 0");
    s.max_lobe_albedo = a.get<double>();
  }
  return s;
}

json clusters_to_json(const ClusterResult& r) {
  json out = {{"format", "brdffit-clusters"}, {"version", 1}, {"model", model_to_json(r.model)},
              {"total_error", r.total_error}};
  json cs = json::array();
  for (std::size_t i = 0; i < r.clusters.size(); ++i) {
    const MaterialCluster& c = r.clusters[i];
    json cov = json::array();
    for (Eigen::Index a = 0; a < c.covariance.rows(); ++a) {
      json row = json::array();
      for (Eigen::Index b = 0; b < c.covariance.cols(); ++b) row.push_back(c.covariance(a, b));
      cov.push_back(row);
    }
    cs.push_back({{"id", i},
                  {"brdf", brdf_to_json(to_brdf(r.model, c.params))},
                  {"params", std::vector<double>(c.params.data(), c.params.data() + c.params.size())},
                  {"covariance", cov},
                  {"members", c.members},
                  {"samples", c.samples},
                  {"error", c.error}});
  }
  out["clusters"] = cs;
  json h = json::array();
  for (const SplitRecord& s : r.history)
    h.push_back({{"split", s.split},
                 {"created", s.created},
                 {"clusters", s.clusters},
                 {"split_iterations", s.split_iterations},
                 {"error_before", s.error_before},
                 {"error_after", s.error_after}});
  out["history"] = h;
  return out;
}

ClusterResult clusters_from_json(const json& j) {
  if (!j.is_object()) throw bad_input("clusters: expected a JSON object");
  ClusterResult r;
  r.model = model_from_json(field(j, "model", "clusters"));
  const auto np = static_cast<Eigen::Index>(parameter_count(r.model));
  const json& cs = field(j, "clusters", "clusters");
  if (!cs.is_array() || cs.empty()) throw bad_input("clusters: \"clusters\" must be a non-empty list");
  if (cs.size() > 65535) throw bad_input("clusters: at most 65535 clusters");
  for (const json& c : cs) {
    MaterialCluster m;
    m.params = vector_from(field(c, "params", "clusters[]"), "clusters[].params", np);
    const json& cov = field(c, "covariance", "clusters[]");
    if (!cov.is_array() || static_cast<Eigen::Index>(cov.size()) != np)
      throw bad_input("clusters[].covariance: expected {} rows", np);
    m.covariance.resize(np, np);
    for (Eigen::Index a = 0; a < np; ++a)
      m.covariance.row(a) = vector_from(cov[static_cast<std::size_t>(a)], "clusters[].covariance", np).transpose();
    if (c.contains("members") && c.at("members").is_number_unsigned()) m.members = c.at("members").get<std::size_t>();
    if (c.contains("samples") && c.at("samples").is_number_unsigned()) m.samples = c.at("samples").get<std::size_t>();
    if (c.contains("error") && c.at("error").is_number()) m.error = c.at("error").get<double>();
    r.clusters.push_back(std::move(m));
  }
  if (j.contains("total_error") && j.at("total_error").is_number()) r.total_error = j.at("total_error").get<double>();
  return r;
}

}  // namespace fest::brdffit
