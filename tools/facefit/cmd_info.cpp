// facefit info: a model described as JSON.

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

int run_info(const InfoArgs& a) {
  const std::string path = model_path(a.model);
  const facefit::Model m = load_model(a.model, a.fix_basis);
  nlohmann::json j = {{"file", path},
                      {"format", "mmb"},
                      {"dims", m.dims},
                      {"points", m.points},
                      {"components", m.components},
                      {"units", m.units},
                      {"source", m.source},
                      {"license", m.license},
                      {"training_examples", m.training_examples},
                      {"basis_dtype", m.basis_type == facefit::Dtype::f32 ? "f32" : "f64"},
                      {"triangles", m.triangles.size()},
                      {"landmarks", m.landmarks.size()},
                      {"eval_mask", m.eval_mask.size()},
                      {"sigma_first", m.sigma.front()},
                      {"sigma_last", m.sigma.back()},
                      {"total_stddev", 0.0}};
  double var = 0;
  for (double s : m.sigma) var += s * s;
  j["total_stddev"] = std::sqrt(var);
  j["rms_per_vertex"] = std::sqrt(var / static_cast<double>(m.points));
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t p = 0; p < m.points; ++p)
    for (int e = 0; e < m.dims; ++e) {
      lo[e] = std::min(lo[e], m.mean[p * static_cast<std::size_t>(m.dims) + static_cast<std::size_t>(e)]);
      hi[e] = std::max(hi[e], m.mean[p * static_cast<std::size_t>(m.dims) + static_cast<std::size_t>(e)]);
    }
  j["mean_bbox"] = {{"min", std::vector<double>(lo, lo + m.dims)}, {"max", std::vector<double>(hi, hi + m.dims)}};
  write_output("-", formats::write_json(j));
  return 0;
}

}  // namespace fest::facefit_tool
