// segbrain slices: three orthogonal slices of a volume, with its labels overlaid when
// --labels is given, as one PNG with orientation letters and a scale bar, so a person can
// look at a volume or a segmentation (pictures for review, segbrain(1)). The drawing is
// lib/core/volume_view's (the same as fconv's quick look).
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/image.hpp"
#include "core/volume_view.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/volume/orientation_stated.hpp"
#include "formats/volume/volume_io.hpp"
#include "knowledge_base.hpp"
#include "volume_files.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

int run_slices(const SlicesArgs& a) {
  const formats::Input in = formats::load_input(a.input);
  if (formats::kind_of(in.format) != formats::Kind::volume)
    throw bad_input("expected a volume (NIfTI, NRRD, MHA), got {} ({})", formats::format_name(in.format), in.name);
  Volume img = formats::parse(in, formats::read_volume);
  img.require_3d(fmt::format("segbrain slices ({})", in.name).c_str());
  if (img.size() == 0) throw bad_input("volume has no voxels ({})", a.input);

  VolumeViewOptions view;
  view.orientation_known = formats::volume_orientation_stated(in);
  view.pixel_mm = std::min({img.spacing[0], img.spacing[1], img.spacing[2]}) / a.scale;
  Volume lab;
  std::map<int, std::array<int, 3>> colours;
  if (!a.labels.empty()) {
    lab = read_volume_input(a.labels, "segbrain slices");
    if (img.dims != lab.dims)
      throw bad_input("volume {}x{}x{} and labels {}x{}x{} differ in size", img.dims[0], img.dims[1], img.dims[2],
                      lab.dims[0], lab.dims[1], lab.dims[2]);
    for (const auto& l : kb_labels(a.kb)) colours[l.index] = l.rgb;
    // Slices through the centroid of the labels above 1 (inside the head's outer layer),
    // else through the centre.
    double s[3] = {0, 0, 0};
    std::size_t n = 0;
    for (std::size_t z = 0; z < img.dims[2]; ++z)
      for (std::size_t y = 0; y < img.dims[1]; ++y)
        for (std::size_t x = 0; x < img.dims[0]; ++x)
          if (lab.at(x, y, z) > 1) s[0] += double(x), s[1] += double(y), s[2] += double(z), ++n;
    if (n > 0) {
      std::array<std::size_t, 3> at{};
      for (int k = 0; k < 3; ++k) at[k] = static_cast<std::size_t>(std::lround(s[k] / double(n)));
      view.slice = at;
    }
    view.tint = [&lab, &colours](std::size_t index, std::array<double, 3>& rgb) {
      const int label = static_cast<int>(lab.voxels[index]);
      const auto it = colours.find(label);
      if (label <= 0 || it == colours.end()) return;
      const double alpha = label == 1 ? 0.15 : 0.45;  // the scalp only tinted
      for (std::size_t k = 0; k < 3; ++k) rgb[k] = (1 - alpha) * rgb[k] + alpha * it->second[k];
    };
  }
  const VolumeView picture = render_volume_view(img, view);
  formats::store_output(a.output, formats::write_image(fest::Image{picture.rgb, ColorSpace::srgb}, formats::Format::png), false);
  return 0;
}

}  // namespace fest::segbrain_tool
