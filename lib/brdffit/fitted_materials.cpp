#include "brdffit/fitted_materials.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "brdffit/lafortune_model.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

reflectance::SurfaceMaterials materials_from_projection(const Projection& p, const LumitexelSet& set,
                                                        std::size_t triangles) {
  if (p.cluster.size() != set.lumitexels.size())
    throw bad_input("the weights hold {} lumitexels, the lumitexel file {}", p.cluster.size(), set.lumitexels.size());
  const std::size_t k = p.basis.cluster_basis.size();
  if (k == 0) throw bad_input("the weights name no cluster");
  reflectance::SurfaceMaterials m;
  for (const std::vector<int>& list : p.basis.cluster_basis) {
    if (list.empty() || list[0] < 0 || static_cast<std::size_t>(list[0]) >= p.basis.brdfs.size())
      throw bad_input("a cluster's basis does not start with a BRDF of the basis list");
    m.brdfs.push_back(to_brdf(p.basis.model, p.basis.brdfs[static_cast<std::size_t>(list[0])]));
  }
  // Votes per (triangle, cluster); lumitexels without samples do not vote.
  std::vector<std::uint32_t> votes(triangles * k, 0), total(k, 0);
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i) {
    const Lumitexel& l = set.lumitexels[i];
    if (l.triangle >= triangles)
      throw bad_input("lumitexel {} lies on triangle {}, the mesh has {}", i, l.triangle, triangles);
    if (p.cluster[i] >= k) throw bad_input("lumitexel {} is in cluster {} of {}", i, p.cluster[i], k);
    if (l.count == 0) continue;
    ++votes[l.triangle * k + p.cluster[i]];
    ++total[p.cluster[i]];
  }
  const auto fallback = static_cast<std::uint16_t>(std::max_element(total.begin(), total.end()) - total.begin());
  m.triangle_material.assign(triangles, fallback);
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto first = votes.begin() + static_cast<long>(t * k);
    const auto best = std::max_element(first, first + static_cast<long>(k));  // ties: lower cluster
    if (*best > 0) m.triangle_material[t] = static_cast<std::uint16_t>(best - first);
  }
  return m;
}

}  // namespace fest::brdffit
