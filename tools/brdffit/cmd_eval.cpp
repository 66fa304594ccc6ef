// brdffit eval (docs/brdffit.md §6): a rendering against a photograph
// (lib/brdffit/image_metrics) -> RMSE, relative L2 and PSNR as JSON.

#include <cmath>
#include <string>

#include "brdffit/image_metrics.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

int run_eval(const EvalArgs& a) {
  cv::Mat p, r, pv, rv;
  load_radiance(a.photo, p, pv);
  load_radiance(a.render, r, rv);
  cv::Mat mask;
  if (!a.mask.empty()) mask = load_mask(a.mask);
  brdffit::RenderError e;
  try {
    e = brdffit::compare_renderings(p, r, mask);
  } catch (const Error& err) {
    throw Error(err.status(), with_location(err.what(), a.photo + ", " + a.render));
  }
  nlohmann::json j{{"photo", a.photo},
                   {"render", a.render},
                   {"pixels", e.pixels},
                   {"rmse", e.rmse},
                   {"relative_l2", e.relative_l2},
                   {"psnr_db", std::isfinite(e.psnr_db) ? nlohmann::json(e.psnr_db) : nlohmann::json("inf")},
                   {"exposure", e.exposure}};
  std::string err_bytes;
  if (!a.error.empty()) err_bytes = encode_exr(e.error);
  if (!a.error.empty()) write_output(a.error, err_bytes);
  write_output(a.out, formats::write_json(j));
  return 0;
}

}  // namespace fest::brdffit_tool
