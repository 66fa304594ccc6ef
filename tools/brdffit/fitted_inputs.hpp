#pragma once
// The materials side's files as the later stages read them: .ltx lumitexels, .ltw
// weights, and the per-triangle materials they imply (docs/brdffit.md §4-6).

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "brdffit/lumitexel.hpp"
#include "brdffit/project.hpp"
#include "core/error.hpp"
#include "reflectance/render.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

// Runs `decode`; a bad_input error from it names `where` (the file it read).
template <typename Decode>
auto decoded_from(const std::string& where, Decode&& decode) -> decltype(decode()) {
  try {
    return decode();
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), where));
  }
}

// A .ltx file ("-" = standard input); its JSON header into *header when given.
brdffit::LumitexelSet load_lumitexels(const std::string& path, nlohmann::json* header);

// Lumitexels with fewer than min_samples samples take no part (their count is set to 0
// in the copy used); refuses a set where none is left. Returns how many are kept.
std::size_t drop_sparse(brdffit::LumitexelSet& set, int min_samples);

// The fitted result: the .ltw weights and the .ltx lumitexels they were made from, both
// checked against the mesh.
struct FittedInputs {
  brdffit::Projection projection;
  brdffit::LumitexelSet set;
};
FittedInputs load_fitted(const LoadedMesh& lm, const std::string& mesh_path, const std::string& svbrdf,
                         const std::string& ltx);

// Every triangle takes the BRDF of its lumitexels' majority cluster; triangles without
// lumitexels take their neighbours' (materials_from_projection).
reflectance::SurfaceMaterials fitted_materials(const FittedInputs& f, const LoadedMesh& lm, const std::string& where);

}  // namespace fest::brdffit_tool
