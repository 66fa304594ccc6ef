// facefit sample: faces from coefficients, at random, or the mean.

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

namespace fest::facefit_tool {

using namespace fest;

int run_sample(const SampleArgs& a) {
  const facefit::Model m = load_model(a.model);
  const auto k = static_cast<Eigen::Index>(m.components);
  std::vector<Eigen::VectorXd> coeffs;
  if (!a.coeffs.empty()) {
    const Table t = formats::read_table(read_input(a.coeffs), formats::Format::tsv);
    const std::size_t ci = t.find("c"), ii = t.find("index");
    if (ci == Table::npos) throw bad_input("coefficient table needs a column 'c' ({})", a.coeffs);
    Eigen::VectorXd c = Eigen::VectorXd::Zero(k);
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const double idx = ii == Table::npos ? static_cast<double>(r) : t.columns[ii][r];
      if (!(idx >= 0 && idx < static_cast<double>(k)) || idx != std::floor(idx))
        throw bad_input("coefficient index {} outside 0..{} ({})", idx, k - 1, a.coeffs);
      if (!std::isfinite(t.columns[ci][r])) throw bad_input("coefficient {} is not finite ({})", idx, a.coeffs);
      c(static_cast<Eigen::Index>(idx)) = t.columns[ci][r];
    }
    coeffs.push_back(c);
  } else if (a.random > 0) {
    facefit::Rng rng(a.seed);
    for (int i = 0; i < a.random; ++i) {
      Eigen::VectorXd c(k);
      for (Eigen::Index j = 0; j < k; ++j) c(j) = a.sigma_scale * rng.normal();
      coeffs.push_back(c);
    }
  } else {
    coeffs.push_back(Eigen::VectorXd::Zero(k));  // the mean face
  }
  if (coeffs.size() == 1) {
    write_shape(facefit::reconstruct(m, coeffs[0]), m.dims, m.triangles, a.output, a.to);
    return 0;
  }
  if (is_stdio(a.output)) throw usage_error("--random {} writes several meshes: -o must name a folder", a.random);
  ::mkdir(a.output.c_str(), 0777);
  for (std::size_t i = 0; i < coeffs.size(); ++i)
    write_mesh_to(shape_to_mesh(facefit::reconstruct(m, coeffs[i]), m.dims, m.triangles),
                  fmt::format("{}/sample{:03d}.ply", a.output, i + 1), a.to);
  return 0;
}

}  // namespace fest::facefit_tool
