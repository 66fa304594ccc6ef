#pragma once
// Quick-look pictures of a volume (fconv VOLUME --to png, segbrain slices; docs/fconv.md
// "Volume quick look"): three orthogonal slices, a montage of axial slices, or maximum
// intensity projections, each panel labelled with the patient directions at its edges
// (L/R, P/A, I/S) and the sheet with a scale bar of a round length in mm.
//
// Voxel axes are permuted and flipped to the nearest of the world's R, A, S axes, never
// resampled; panels keep the voxels' physical aspect (square display pixels of
// pixel_mm). The default convention is neurological: the patient's left is on the
// image's left (radiological swaps left and right in the axial and coronal panels).

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/volume.hpp"

namespace fest {

enum class VolumeViewKind { ortho, montage, mip };
enum class DisplayConvention { neurological, radiological };

const char* volume_view_kind_name(VolumeViewKind k) noexcept;          // "ortho", ...
const char* display_convention_name(DisplayConvention c) noexcept;    // "neurological", ...

struct VolumeViewOptions {
  VolumeViewKind kind = VolumeViewKind::ortho;
  // ortho: the voxel (i, j, k) in the volume's own voxel order that the three slices
  // pass through; default the centre voxel.
  std::optional<std::array<std::size_t, 3>> slice;
  // Grey window [lo, hi]; default robust_window.
  std::optional<std::array<double, 2>> window;
  DisplayConvention convention = DisplayConvention::neurological;
  // False when the file states no orientation: voxel axes are shown as they are, the
  // panels are named by voxel axes and the sheet says "orientation unknown".
  bool orientation_known = true;
  double pixel_mm = 0;      // display pixel size; 0 = automatic (the finest voxel spacing, enlarged for small volumes)
  int montage_slices = 12;  // montage: this many axial slices, evenly spaced over those with content
  // Slices (not projections): may change the grey colour (0..255 each, R G B) of a pixel
  // showing voxel `index` (index into Volume::voxels) -- label overlays.
  std::function<void(std::size_t index, std::array<double, 3>& rgb)> tint;
};

// One panel of the sheet: where it is (pixels), and the direction named at each edge
// ("" when the orientation is unknown).
struct ViewPanel {
  std::string title;
  int x = 0, y = 0, width = 0, height = 0;
  std::string left, right, top, bottom;
};

struct VolumeView {
  cv::Mat rgb;  // CV_8UC3, R G B
  std::vector<ViewPanel> panels;
  double pixel_mm = 0;
  double scale_bar_mm = 0;
  int scale_bar_px = 0;
  std::array<double, 2> window{0, 1};
  double obliquity_deg = 0;  // largest angle between a voxel axis and the world axis it is shown as
  std::string note;          // "" or "orientation unknown" / "oblique ..."
};

// The 1st and `upper` (default 99th) percentiles of the finite non-zero voxels of the
// first frame (every voxel of small volumes, an evenly spaced sample of large ones); a
// constant volume gives [0, value] (or [value, value + 1] for values <= 0); [0, 1] when
// all are zero. Projections (mip) take their default window from the projected values,
// 1st to 99.5th percentile.
std::array<double, 2> robust_window(const Volume& v, double upper = 0.99);

// The largest length 1, 2 or 5 times a power of ten that is at most `limit_mm`.
double round_scale_length(double limit_mm) noexcept;

// Draws the view of the first frame of `v`. Throws usage_error when options.slice lies
// outside the volume, bad_input when the volume has no voxels.
VolumeView render_volume_view(const Volume& v, const VolumeViewOptions& options);

}  // namespace fest
