#pragma once
// JSON forms of brdffit's materials results (brdffit(1)): brdf.json (one
// Lafortune BRDF) and clusters.json (model, per-cluster parameters and covariance,
// members, errors, split history). Readers validate and throw bad_input naming the field.

#include <nlohmann/json.hpp>

#include "brdffit/cluster.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

// {"model":"lafortune","lobes":K,"rho_d":[3],"Cxy":[[3]xK],"Cz":[[3]xK],"N":[[3]xK]}
nlohmann::json brdf_to_json(const reflectance::LafortuneBrdf& brdf);
reflectance::LafortuneBrdf brdf_from_json(const nlohmann::json& j);

nlohmann::json model_to_json(const ModelSpec& spec);
ModelSpec model_from_json(const nlohmann::json& j);

// clusters.json; parameters are stored in the fitting layout (log N) next to the
// readable BRDF, so that `project` can split again with the covariance.
nlohmann::json clusters_to_json(const ClusterResult& result);
ClusterResult clusters_from_json(const nlohmann::json& j);  // assignment is left empty

}  // namespace fest::brdffit
