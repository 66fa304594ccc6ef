// A model from example meshes in correspondence (build, convert --from ply-set), and the
// landmark map and evaluation mask stored with it.

#include <sys/stat.h>

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "model_assembly.hpp"
#include "face_files.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "facefit/pca_build.hpp"
#include "facefit/rng.hpp"
#include "formats/facemodel/import.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/table/table_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

facefit::Model build_from_meshes(const std::vector<std::string>& paths, const BuildArgs& a) {
  if (paths.size() < 2) throw usage_error("build needs at least 2 example meshes");
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Eigen::VectorXd first = read_shape(paths[0], &triangles);
  Eigen::MatrixXd X(first.size(), static_cast<Eigen::Index>(paths.size()));
  X.col(0) = first;
  // --progress: the meshes read, then the PCA as one more step.
  Progress bar("facefit build", paths.size() + 1, progress_wanted(a.progress));
  bar.advance();
  for (std::size_t i = 1; i < paths.size(); ++i) {
    const Eigen::VectorXd v = read_shape(paths[i]);
    if (v.size() != first.size())
      throw bad_input("'{}' has {} vertices, '{}' has {}: meshes must be in correspondence", paths[i], v.size() / 3, paths[0],
                      first.size() / 3);
    X.col(static_cast<Eigen::Index>(i)) = v;
    bar.advance();
  }
  facefit::BuildOptions o;
  if (a.components < 0) throw usage_error("--components must be positive");
  o.components = static_cast<std::size_t>(a.components);
  if (a.variance < 0 || a.variance > 1) throw usage_error("--variance must be in (0, 1]");
  o.variance = a.variance;
  o.float_basis = !a.f64;
  facefit::Model m = facefit::build_model(X, 3, o);
  bar.finish();
  m.triangles = triangles;
  m.units = a.units;
  m.source = fmt::format("facefit build from {} meshes", paths.size());
  return m;
}

void attach_landmarks(facefit::Model& m, const std::string& landmarks, const std::string& mask) {
  if (!landmarks.empty()) m.landmarks = read_map(landmarks);
  if (!mask.empty()) m.eval_mask = read_vertex_indices(mask);
  facefit::check_model(m, false);
}

}  // namespace fest::facefit_tool
