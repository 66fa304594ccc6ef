#include "fitted_inputs.hpp"

#include <cstdint>
#include <vector>

#include "brdffit/fitted_materials.hpp"
#include "brdffit/ltw_format.hpp"
#include "brdffit/ltx_format.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"

namespace fest::brdffit_tool {

brdffit::LumitexelSet load_lumitexels(const std::string& path, nlohmann::json* header) {
  const std::string bytes = read_input(path);
  return decoded_from(input_name(path), [&] {
    return brdffit::decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), header);
  });
}

std::size_t drop_sparse(brdffit::LumitexelSet& set, int min_samples) {
  if (min_samples < 1) throw usage_error("--min-samples must be at least 1");
  std::size_t kept = 0;
  for (brdffit::Lumitexel& l : set.lumitexels) {
    if (l.count < min_samples) l.count = 0;
    else ++kept;
  }
  if (kept == 0) throw bad_input("no lumitexel has >= {} samples", min_samples);
  return kept;
}

FittedInputs load_fitted(const LoadedMesh& lm, const std::string& mesh_path, const std::string& svbrdf,
                         const std::string& ltx) {
  if (ltx.empty()) throw usage_error("--svbrdf needs --ltx, the lumitexel file the weights were made from");
  FittedInputs f;
  nlohmann::json wh;
  f.projection = decoded_from(svbrdf, [&] { return brdffit::decode_ltw(read_input(svbrdf), &wh); });
  const std::string bytes = read_input(ltx);
  f.set = decoded_from(ltx, [&] {
    return brdffit::decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), nullptr);
  });
  if (f.set.mesh_sha256 != lm.sha256)
    throw bad_input("the mesh does not match the lumitexel file: SHA-256 {} vs {} ({}, {})", lm.sha256.substr(0, 16),
                    f.set.mesh_sha256.substr(0, 16), mesh_path, ltx);
  if (wh.contains("mesh_sha256") && wh["mesh_sha256"].is_string() && wh["mesh_sha256"] != lm.sha256)
    throw bad_input("the weights were made for another mesh (mesh_sha256 differs) ({})", svbrdf);
  return f;
}

reflectance::SurfaceMaterials fitted_materials(const FittedInputs& f, const LoadedMesh& lm, const std::string& where) {
  return decoded_from(where, [&] {
    return brdffit::materials_from_projection(f.projection, f.set, lm.mesh.triangles);
  });
}

}  // namespace fest::brdffit_tool
