// fcompare on images: RMSE, PSNR and max abs, per channel and over all; alpha apart.

#include <nlohmann/json.hpp>

#include "compare/image_compare.hpp"
#include "formats/image/image_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

void compare_images(const Input& ia, const Input& ib, const CompareOptions& opt, Metrics& m) {
  const auto [a, b] = parse_both(ia, ib, read_image);
  const auto e = compare::image_error(a.pixels, b.pixels);
  m.set("rmse", e.all.rmse);
  m.set("psnr", e.all.psnr);
  m.set("max_abs", e.all.max_abs);
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& c : e.channels)
    channels.push_back({{"rmse", c.rmse}, {"psnr", compare::json_number(c.psnr)}, {"max_abs", c.max_abs}});
  m.details["channels"] = channels;
  m.details["peak"] = e.peak;
  if (e.alpha.measured) {
    // Only one image has alpha: the other is opaque, so its distance from opaque is
    // the alpha difference, reported and checked on its own.
    m.set("alpha_max_abs", e.alpha.max_abs);
    m.details["alpha"] = {{"in", e.alpha.image == 1 ? "a" : "b"}, {"min", e.alpha.min_alpha}};
    require_main(m, "alpha_max_abs", opt);
  }
  m.family({"max_abs", "rmse", "psnr"});
  require_main(m, "max_abs", opt);
}

}  // namespace fest::fcompare_tool
