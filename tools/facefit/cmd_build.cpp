// facefit build: a PCA model from example meshes in correspondence.

#include <sys/stat.h>

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "face_files.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "facefit/pca_build.hpp"
#include "facefit/rng.hpp"
#include "formats/facemodel/import.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/table/table_io.hpp"
#include "model_assembly.hpp"

namespace fest::facefit_tool {

using namespace fest;

int run_build(const BuildArgs& a) {
  std::vector<std::string> paths = a.examples;
  if (!a.list.empty())
    for (auto& p : read_list(a.list)) paths.push_back(p);
  facefit::Model m = build_from_meshes(paths, a);
  attach_landmarks(m, a.landmarks, a.mask);
  write_output(a.output, formats::write_mmb(m));
  return 0;
}

}  // namespace fest::facefit_tool
