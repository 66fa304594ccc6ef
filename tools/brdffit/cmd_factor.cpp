// brdffit factor (docs/brdffit.md §6): brdf.json -> lib/brdffit/separable -> PREFIXg.exr,
// PREFIXh.exr and a JSON report of the rank-1 errors on standard output.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "brdffit/separable.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/table/table_io.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {
namespace {

// One factor as an image: rows theta (0 at the pole), columns phi.
cv::Mat factor_image(const std::vector<Eigen::Vector3d>& v, int theta_bins, int phi_bins) {
  cv::Mat img(theta_bins, phi_bins, CV_32FC3);
  for (int t = 0; t < theta_bins; ++t)
    for (int p = 0; p < phi_bins; ++p) {
      const Eigen::Vector3d& x = v[static_cast<std::size_t>(t) * static_cast<std::size_t>(phi_bins) + static_cast<std::size_t>(p)];
      img.at<cv::Vec3f>(t, p) = cv::Vec3f(static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2]));
    }
  return img;
}

nlohmann::json error_json(const brdffit::SeparableFactors& f) {
  return {{"relative_rms", f.relative_rms_all},
          {"relative_rms_rgb", {f.relative_rms[0], f.relative_rms[1], f.relative_rms[2]}},
          {"iterations", f.iterations}};
}

}  // namespace

int run_factor(const FactorArgs& a) {
  if (a.theta_bins * a.phi_bins > 4096)
    throw usage_error("--theta-bins {} x --phi-bins {}: at most 4096 directions", a.theta_bins, a.phi_bins);
  const reflectance::LafortuneBrdf brdf = brdf_from_json(load_json(a.brdf), a.brdf);
  brdffit::SeparableOptions o;
  o.theta_bins = a.theta_bins;
  o.phi_bins = a.phi_bins;
  o.threads = resolve_threads(a.threads);
  const brdffit::SeparableFactors hd = brdffit::factor_brdf(brdf, brdffit::SeparableGrid::half_difference, o);
  nlohmann::json report{{"brdf", a.brdf},
                        {"grid", {{"theta_bins", a.theta_bins}, {"phi_bins", a.phi_bins}}},
                        {"g", a.prefix + "g.exr"},
                        {"h", a.prefix + "h.exr"},
                        {"half_difference", error_json(hd)}};
  if (!a.no_compare)
    report["out_in"] = error_json(brdffit::factor_brdf(brdf, brdffit::SeparableGrid::out_in, o));
  const std::string g = encode_exr(factor_image(hd.g, a.theta_bins, a.phi_bins));
  const std::string h = encode_exr(factor_image(hd.h, a.theta_bins, a.phi_bins));
  AtomicFile gf(a.prefix + "g.exr"), hf(a.prefix + "h.exr");
  write_output(gf.temp_path(), g);
  write_output(hf.temp_path(), h);
  gf.commit();
  hf.commit();
  write_output("-", formats::write_json(report));
  return 0;
}

}  // namespace fest::brdffit_tool
