// brdffit info (docs/brdffit.md §4): a .ltx file described as JSON; with --mesh, checked
// against that mesh's SHA-256.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "brdffit/ltx_format.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

int run_info(const InfoArgs& a) {
  const std::string bytes = read_input(a.in);
  nlohmann::json header;
  brdffit::LumitexelSet set;
  try {
    set = brdffit::decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), &header);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), a.in));
  }
  if (!a.mesh.empty()) {
    const LoadedMesh lm = load_mesh(a.mesh);
    if (lm.sha256 != set.mesh_sha256)
      throw bad_input("the mesh does not match the lumitexel file: SHA-256 {} vs {} ({}, {})", lm.sha256.substr(0, 16),
                      set.mesh_sha256.substr(0, 16), a.mesh, a.in);
  }
  std::size_t max_count = 0;
  for (const auto& l : set.lumitexels) max_count = std::max<std::size_t>(max_count, l.count);
  nlohmann::json j{{"lumitexels", set.lumitexels.size()},
                   {"samples", set.samples.size()},
                   {"mean_samples", set.lumitexels.empty() ? 0.0
                                                           : static_cast<double>(set.samples.size()) /
                                                                 static_cast<double>(set.lumitexels.size())},
                   {"max_samples", max_count},
                   {"images", set.images.size()},
                   {"mesh_sha256", set.mesh_sha256},
                   {"mesh_matches", a.mesh.empty() ? nlohmann::json(nullptr) : nlohmann::json(true)}};
  write_output("-", formats::write_json(j));
  return 0;
}

}  // namespace fest::brdffit_tool
