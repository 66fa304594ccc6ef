// hdrmerge bracket: a simulated camera exposing a radiance image into 8-bit PNGs
// DIR/e00.png, e01.png, ... (the layout of capture's series), with the true response.

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <opencv2/core.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "stack_files.hpp"

namespace fest::hdrmerge_tool {

int run_bracket(const BracketOptions& a) {
  const std::vector<double>& times = a.times;
  Image radiance = formats::parse(formats::load_input(a.radiance), formats::read_image);
  if (radiance.pixels.depth() != CV_32F)
    throw bad_input("{}-bit integer image; bracketing needs float radiance (EXR or PFM) ({})",
                    radiance.pixels.depth() == CV_8U ? 8 : 16, a.radiance);
  if (radiance.pixels.channels() == 2 || radiance.pixels.channels() == 4) {
    // Alpha is not light: keep grey or RGB.
    std::vector<cv::Mat> planes;
    cv::split(radiance.pixels, planes);
    planes.pop_back();
    cv::merge(planes, radiance.pixels);
  }
  std::vector<std::string> encoded;
  Progress bar("hdrmerge bracket", times.size(), progress_wanted(a.progress));
  for (std::size_t k = 0; k < times.size(); ++k) {
    const cv::Mat z = hdr::expose(radiance.pixels * a.scale, times[k], a.camera, a.seed + k);
    encoded.push_back(formats::write_image(Image{z, ColorSpace::srgb}, formats::Format::png));
    bar.advance();
  }
  bar.finish();
  std::string curve;
  if (!a.response_out.empty()) {
    hdr::Response r;
    hdr::Curve g{};
    // z = 0 carries no weight anywhere; one step below z = 1 keeps the curve finite.
    g[0] = hdr::model_log_inverse(a.camera, 1) - a.camera.gamma * std::log(2.0);
    for (int z = 1; z < hdr::kCodes; ++z) g[std::size_t(z)] = hdr::model_log_inverse(a.camera, z);
    r.g.assign(std::size_t(radiance.pixels.channels()), g);
    curve = formats::write_table(response_table(r), formats::Format::csv);
  }
  for (std::size_t k = 0; k < encoded.size(); ++k)
    write_output(fmt::format("{}/e{:02}.png", a.directory, k), encoded[k]);
  if (!a.response_out.empty()) write_output(a.response_out, curve);
  return 0;
}

}  // namespace fest::hdrmerge_tool
