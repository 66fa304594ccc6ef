#include "facefit/landmark_set.hpp"

#include "core/error.hpp"

namespace fest::facefit {

Landmarks resolve_landmarks(const std::vector<LandmarkEntry>& entries, const LandmarkMap& map, bool skip_unmapped,
                            std::size_t* skipped, const std::string& source) {
  Landmarks lm;
  std::vector<double> u, v, sigma;
  bool any_sigma = false;
  std::size_t missing = 0;
  for (const auto& e : entries) {
    std::uint32_t vertex = e.vertex;
    if (!e.by_vertex) {
      auto it = map.find(e.id);
      if (it == map.end()) {
        if (!skip_unmapped)
          throw bad_input("landmark id '{}' is not in the landmark map ({}:{})", e.id, source, e.line);
        ++missing;
        continue;
      }
      vertex = it->second;
    }
    lm.vertex.push_back(vertex);
    lm.id.push_back(e.by_vertex ? "v" + std::to_string(vertex) : e.id);
    u.push_back(e.u);
    v.push_back(e.v);
    sigma.push_back(e.sigma);
    any_sigma = any_sigma || e.sigma > 0;
  }
  if (skipped) *skipped = missing;
  lm.uv.resize(2, static_cast<Eigen::Index>(u.size()));
  for (std::size_t a = 0; a < u.size(); ++a) lm.uv.col(static_cast<Eigen::Index>(a)) << u[a], v[a];
  if (any_sigma) {
    lm.sigma.resize(static_cast<Eigen::Index>(sigma.size()));
    for (std::size_t a = 0; a < sigma.size(); ++a) {
      if (!(sigma[a] > 0)) throw bad_input("landmark '{}': the sigma column needs a positive value on every row ({})", lm.id[a], source);
      lm.sigma(static_cast<Eigen::Index>(a)) = sigma[a];
    }
  }
  return lm;
}

}  // namespace fest::facefit
