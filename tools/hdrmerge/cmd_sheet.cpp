// hdrmerge sheet: a contact sheet of radiance images (e.g. a session's merged EXRs) as
// one PNG, one exposure for all.

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "hdr/contact_sheet.hpp"

namespace fest::hdrmerge_tool {

int run_sheet(const SheetOptions& a) {
  std::vector<cv::Mat> radiance;
  for (const std::string& path : a.images) {
    const Image image = formats::parse(formats::load_input(path), formats::read_image);
    if (image.pixels.depth() != CV_32F) throw bad_input("not a radiance image (EXR or PFM) ({})", path);
    cv::Mat m = image.pixels;
    if (m.channels() == 4 || m.channels() == 2) {
      std::vector<cv::Mat> planes;
      cv::split(m, planes);
      planes.pop_back();
      cv::merge(planes, m);
    }
    radiance.push_back(m);
  }
  const cv::Mat sheet = hdr::contact_sheet(radiance, a.columns, a.width);
  write_output(a.output, formats::write_image(Image{sheet, ColorSpace::srgb}, formats::Format::png));
  return 0;
}

}  // namespace fest::hdrmerge_tool
