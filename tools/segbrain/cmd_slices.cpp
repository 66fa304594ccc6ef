// segbrain slices: three orthogonal slices of a volume with its labels overlaid, as one
// PNG, so a person can look at a segmentation (pictures for review, segbrain(1)).
#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/core.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "knowledge_base.hpp"
#include "segbrain/canonical.hpp"
#include "volume_files.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

namespace {

// One panel: canonical axes (u, v) of the slice `fixed` = `at`, u to the right, v up,
// square pixels of `pixel` mm (nearest voxel).
cv::Mat panel(const Grid& g, const segbrain::Image& grey, const std::vector<float>& labels, int u, int v, int fixed, std::size_t at,
              double pixel, double lo, double hi, const std::map<int, std::array<int, 3>>& colours) {
  const int w = std::max(1, static_cast<int>(std::lround(double(g.n[u]) * g.spacing[u] / pixel)));
  const int h = std::max(1, static_cast<int>(std::lround(double(g.n[v]) * g.spacing[v] / pixel)));
  cv::Mat out(h, w, CV_8UC3);
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      std::array<std::size_t, 3> p{};
      p[fixed] = at;
      p[u] = std::min(g.n[u] - 1, static_cast<std::size_t>((col + 0.5) * pixel / g.spacing[u]));
      p[v] = std::min(g.n[v] - 1, static_cast<std::size_t>((h - 1 - row + 0.5) * pixel / g.spacing[v]));
      const std::size_t i = g.index(p[0], p[1], p[2]);
      double t = hi > lo ? (grey[i] - lo) / (hi - lo) : 0;
      double c[3];
      c[0] = c[1] = c[2] = 255 * std::clamp(t, 0.0, 1.0);
      const int label = static_cast<int>(labels[i]);
      auto it = colours.find(label);
      if (label > 0 && it != colours.end()) {
        const double alpha = label == 1 ? 0.15 : 0.45;  // the scalp only tinted
        for (int k = 0; k < 3; ++k) c[k] = (1 - alpha) * c[k] + alpha * it->second[k];
      }
      auto& px = out.at<cv::Vec3b>(row, col);
      for (int k = 0; k < 3; ++k) px[k] = static_cast<std::uint8_t>(std::lround(c[k]));
    }
  return out;
}

}  // namespace

int run_slices(const SlicesArgs& a) {
  Volume img = read_volume_input(a.input, "segbrain slices");
  Volume lab = read_volume_input(a.labels, "segbrain slices");
  if (img.dims != lab.dims)
    throw bad_input("volume {}x{}x{} and labels {}x{}x{} differ in size", img.dims[0], img.dims[1], img.dims[2], lab.dims[0],
                    lab.dims[1], lab.dims[2]);
  if (img.size() == 0) throw bad_input("volume has no voxels ({})", a.input);
  Reorientation ro = find_reorientation(img);
  Grid g = canonical_grid(img, ro);
  segbrain::Image grey = to_canonical(img, ro);
  for (auto& x : grey)
    if (!std::isfinite(x)) x = 0;
  segbrain::Image labels = to_canonical(lab, ro);

  // Grey window from the 1st and 99th percentiles of the nonzero voxels.
  std::vector<float> vals;
  for (float x : grey)
    if (x != 0) vals.push_back(x);
  double lo = 0, hi = 1;
  if (!vals.empty()) {
    auto nth = [&](double q) {
      auto it = vals.begin() + static_cast<std::ptrdiff_t>(q * double(vals.size() - 1));
      std::nth_element(vals.begin(), it, vals.end());
      return double(*it);
    };
    lo = nth(0.01), hi = nth(0.99);
  }
  // Slices through the centroid of the labels above 1 (inside the head's outer layer),
  // else through the grid centre.
  double s[3] = {0, 0, 0};
  std::size_t n = 0;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x)
        if (labels[g.index(x, y, z)] > 1) s[0] += double(x), s[1] += double(y), s[2] += double(z), ++n;
  std::array<std::size_t, 3> at{};
  for (int k = 0; k < 3; ++k) at[k] = n ? static_cast<std::size_t>(std::lround(s[k] / double(n))) : g.n[k] / 2;

  std::map<int, std::array<int, 3>> colours;
  for (const auto& l : kb_labels(a.kb)) colours[l.index] = l.rgb;
  const double pixel = std::min({g.spacing[0], g.spacing[1], g.spacing[2]}) / a.scale;
  cv::Mat panels[3] = {panel(g, grey, labels, 0, 1, 2, at[2], pixel, lo, hi, colours),   // axial: R right, A up
                       panel(g, grey, labels, 0, 2, 1, at[1], pixel, lo, hi, colours),   // coronal: R right, S up
                       panel(g, grey, labels, 1, 2, 0, at[0], pixel, lo, hi, colours)};  // sagittal: A right, S up
  int height = 0, width = 0;
  for (const auto& p : panels) height = std::max(height, p.rows), width += p.cols;
  cv::Mat sheet(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
  int x0 = 0;
  for (const auto& p : panels) {
    p.copyTo(sheet(cv::Rect(x0, height - p.rows, p.cols, p.rows)));
    x0 += p.cols;
  }
  formats::store_output(a.output, formats::write_image(fest::Image{sheet, ColorSpace::srgb}, formats::Format::png), false);
  return 0;
}

}  // namespace fest::segbrain_tool
