#include "brdffit/fitted_materials.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "brdffit/lafortune_model.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

reflectance::SurfaceMaterials from_votes(const Projection& p, const LumitexelSet& set, std::size_t triangles,
                                         const std::vector<std::array<std::uint32_t, 3>>* faces) {
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
  std::vector<bool> known(triangles, false);
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto first = votes.begin() + static_cast<long>(t * k);
    const auto best = std::max_element(first, first + static_cast<long>(k));  // ties: lower cluster
    if (*best > 0) m.triangle_material[t] = static_cast<std::uint16_t>(best - first), known[t] = true;
  }
  if (faces == nullptr) return m;
  // Gaps (the unseen bottom of an object, say) take their neighbours' majority, one ring
  // per wave; all triangles of a wave decide from the previous waves only, so the result
  // does not depend on the triangles' order. A material boundary through a gap ends up
  // about halfway, where the largest cluster would have painted the whole gap.
  std::vector<std::vector<std::uint32_t>> around;  // triangles per vertex
  for (std::size_t t = 0; t < triangles; ++t)
    for (std::uint32_t v : (*faces)[t]) {
      if (v >= around.size()) around.resize(v + 1);
      around[v].push_back(static_cast<std::uint32_t>(t));
    }
  for (bool grew = true; grew;) {
    grew = false;
    std::vector<std::pair<std::size_t, std::uint16_t>> wave;
    std::vector<std::uint32_t> count(k);
    for (std::size_t t = 0; t < triangles; ++t) {
      if (known[t]) continue;
      std::fill(count.begin(), count.end(), 0);
      for (std::uint32_t v : (*faces)[t])
        for (std::uint32_t u : around[v])
          if (known[u]) ++count[m.triangle_material[u]];
      const auto best = std::max_element(count.begin(), count.end());  // ties: lower cluster
      if (*best > 0) wave.emplace_back(t, static_cast<std::uint16_t>(best - count.begin()));
    }
    for (const auto& [t, c] : wave) m.triangle_material[t] = c, known[t] = true;
    grew = !wave.empty();
  }
  return m;
}

}  // namespace

reflectance::SurfaceMaterials materials_from_projection(const Projection& p, const LumitexelSet& set,
                                                        std::size_t triangles) {
  return from_votes(p, set, triangles, nullptr);
}

reflectance::SurfaceMaterials materials_from_projection(const Projection& p, const LumitexelSet& set,
                                                        const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  return from_votes(p, set, triangles.size(), &triangles);
}

}  // namespace fest::brdffit
