// Quick-look pictures of a volume (docs/fconv.md "Volume quick look").

#include "core/volume_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "core/bitmap_font.hpp"
#include "core/error.hpp"

namespace fest {

namespace {

// The volume's voxel axes in display order: canonical axis a (0 = R, 1 = A, 2 = S) is
// voxel axis src[a], reversed when flip[a]; n and spacing per canonical axis.
struct CanonicalAxes {
  std::array<int, 3> src{0, 1, 2};
  std::array<bool, 3> flip{false, false, false};
  std::array<std::size_t, 3> n{};
  std::array<double, 3> spacing{};
  double obliquity_deg = 0;
};

// Pairs each world axis with the voxel axis closest to it, largest cosine first, so that
// the pairing is a permutation even for oblique volumes.
CanonicalAxes canonical_axes(const Volume& v, bool known) {
  CanonicalAxes c;
  if (known) {
    std::array<bool, 3> row_used{}, col_used{};
    for (int step = 0; step < 3; ++step) {
      int best_r = -1, best_c = -1;
      double best = -1;
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col)
          if (!row_used[r] && !col_used[col] && std::fabs(v.direction[3 * r + col]) > best)
            best = std::fabs(v.direction[3 * r + col]), best_r = r, best_c = col;
      row_used[best_r] = col_used[best_c] = true;
      c.src[best_r] = best_c;
      c.flip[best_r] = v.direction[3 * best_r + best_c] < 0;
      // The columns are unit vectors: the cosine to the world axis is this component.
      c.obliquity_deg = std::max(c.obliquity_deg, std::acos(std::min(1.0, best)) * 180.0 / std::acos(-1.0));
    }
  }
  for (int a = 0; a < 3; ++a) c.n[a] = v.dims[c.src[a]], c.spacing[a] = v.spacing[c.src[a]];
  return c;
}

// Index into Volume::voxels of canonical voxel (c0, c1, c2).
std::size_t voxel_index(const Volume& v, const CanonicalAxes& ax, const std::array<std::size_t, 3>& c) {
  std::array<std::size_t, 3> f{};
  for (int a = 0; a < 3; ++a) f[ax.src[a]] = ax.flip[a] ? ax.n[a] - 1 - c[a] : c[a];
  return v.index(f[0], f[1], f[2]);
}

const char* kNegative[3] = {"L", "P", "I"};
const char* kPositive[3] = {"R", "A", "S"};

// What one panel shows: canonical axes h (to the right, reversed when flip_h) and v (up);
// the slice `at` of axis `fixed`, or the maximum along it.
struct PanelSpec {
  int h = 0, v = 1, fixed = 2;
  bool flip_h = false;
  bool projection = false;
  std::vector<double> mip;  // projections: the maximum along `fixed` at u + n_u * v
  std::size_t at = 0;
  std::string title;
};

// The maximum along the fixed axis for every (u, v) voxel; NaN is ignored.
std::vector<double> projection(const Volume& v, const CanonicalAxes& ax, const PanelSpec& s) {
  const std::size_t nu = ax.n[s.h], nv = ax.n[s.v];
  std::vector<double> mip(nu * nv, -std::numeric_limits<double>::infinity());
  std::array<std::size_t, 3> c{};
  for (std::size_t k = 0; k < ax.n[s.fixed]; ++k)
    for (std::size_t j = 0; j < nv; ++j)
      for (std::size_t i = 0; i < nu; ++i) {
        c[s.fixed] = k, c[s.h] = i, c[s.v] = j;
        const double x = v.voxels[voxel_index(v, ax, c)];
        double& m = mip[i + nu * j];
        if (x > m) m = x;
      }
  return mip;
}

const cv::Scalar kLetterColour(255, 220, 0), kTextColour(200, 200, 200), kBarColour(255, 255, 255);

struct Canvas {
  int scale = 1;
  int pad() const { return 2 * scale + 2; }
  int line() const { return text_height(scale) + 2 * pad(); }
  int letter_margin() const { return kGlyphWidth * scale + 2 * pad(); }
};

unsigned char grey_level(double x, const std::array<double, 2>& w) {
  if (!std::isfinite(x)) return 0;
  const double t = w[1] > w[0] ? (x - w[0]) / (w[1] - w[0]) : 0.0;
  return static_cast<unsigned char>(std::lround(255.0 * std::clamp(t, 0.0, 1.0)));
}

// The pixels of one panel, w x h at pixel_mm per pixel, nearest voxel.
cv::Mat panel_pixels(const Volume& v, const CanonicalAxes& ax, const PanelSpec& s, double pixel_mm,
                     const VolumeViewOptions& o, const std::array<double, 2>& window) {
  const int w = std::max(1, static_cast<int>(std::lround(double(ax.n[s.h]) * ax.spacing[s.h] / pixel_mm)));
  const int h = std::max(1, static_cast<int>(std::lround(double(ax.n[s.v]) * ax.spacing[s.v] / pixel_mm)));
  const std::size_t nu = ax.n[s.h], nv = ax.n[s.v];
  // Column and row of display pixels -> canonical voxel index along h and v.
  std::vector<std::size_t> cu(static_cast<std::size_t>(w)), cv_(static_cast<std::size_t>(h));
  for (int col = 0; col < w; ++col) {
    std::size_t i = std::min(nu - 1, static_cast<std::size_t>((col + 0.5) * pixel_mm / ax.spacing[s.h]));
    cu[static_cast<std::size_t>(col)] = s.flip_h ? nu - 1 - i : i;
  }
  for (int row = 0; row < h; ++row)
    cv_[static_cast<std::size_t>(row)] =
        std::min(nv - 1, static_cast<std::size_t>((h - 1 - row + 0.5) * pixel_mm / ax.spacing[s.v]));
  const std::vector<double>& mip = s.mip;
  cv::Mat out(h, w, CV_8UC3);
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      std::array<std::size_t, 3> c{};
      c[s.fixed] = s.at, c[s.h] = cu[static_cast<std::size_t>(col)], c[s.v] = cv_[static_cast<std::size_t>(row)];
      std::array<double, 3> rgb{};
      if (s.projection) {
        const double g = grey_level(mip[c[s.h] + nu * c[s.v]], window);
        rgb = {g, g, g};
      } else {
        const std::size_t index = voxel_index(v, ax, c);
        const double g = grey_level(v.voxels[index], window);
        rgb = {g, g, g};
        if (o.tint) o.tint(index, rgb);
      }
      auto& px = out.at<cv::Vec3b>(row, col);
      for (int k = 0; k < 3; ++k) px[k] = cv::saturate_cast<unsigned char>(std::lround(rgb[static_cast<std::size_t>(k)]));
    }
  return out;
}

// A cell: the title line, the top letter line, the panel between the side letters, the
// bottom letter line. Returns the cell's size.
cv::Size cell_size(const cv::Mat& pixels, const std::string& title, const Canvas& k) {
  // Two pads more on each side keep the letters of neighbouring cells apart.
  const int w = std::max(pixels.cols + 2 * k.letter_margin(), text_width(title, k.scale)) + 4 * k.pad();
  return {w, 3 * k.line() + pixels.rows};
}

ViewPanel draw_cell(cv::Mat& sheet, int x, int y, const cv::Size& cell, const cv::Mat& pixels, const PanelSpec& s,
                    const CanonicalAxes&, bool known, const Canvas& k) {
  ViewPanel p;
  p.title = s.title;
  p.width = pixels.cols, p.height = pixels.rows;
  p.x = x + (cell.width - pixels.cols) / 2;
  p.y = y + 2 * k.line();
  pixels.copyTo(sheet(cv::Rect(p.x, p.y, p.width, p.height)));
  draw_text(sheet, x + 2 * k.pad(), y + k.pad(), s.title, kTextColour, k.scale);
  if (known) {
    p.left = s.flip_h ? kPositive[s.h] : kNegative[s.h];
    p.right = s.flip_h ? kNegative[s.h] : kPositive[s.h];
    p.top = kPositive[s.v], p.bottom = kNegative[s.v];
    const int lw = kGlyphWidth * k.scale, lh = text_height(k.scale);
    const int mid_x = p.x + p.width / 2 - lw / 2, mid_y = p.y + p.height / 2 - lh / 2;
    draw_text(sheet, p.x - k.pad() - lw, mid_y, p.left, kLetterColour, k.scale);
    draw_text(sheet, p.x + p.width + k.pad(), mid_y, p.right, kLetterColour, k.scale);
    draw_text(sheet, mid_x, p.y - k.pad() - lh, p.top, kLetterColour, k.scale);
    draw_text(sheet, mid_x, p.y + p.height + k.pad(), p.bottom, kLetterColour, k.scale);
  }
  return p;
}

std::string number_text(double x) {
  std::string s = fmt::format("{:.4g}", x);
  return s;
}

}  // namespace

const char* volume_view_kind_name(VolumeViewKind k) noexcept {
  switch (k) {
    case VolumeViewKind::ortho: return "ortho";
    case VolumeViewKind::montage: return "montage";
    case VolumeViewKind::mip: return "mip";
  }
  return "ortho";
}

const char* display_convention_name(DisplayConvention c) noexcept {
  return c == DisplayConvention::radiological ? "radiological" : "neurological";
}

std::array<double, 2> robust_window(const Volume& v, double upper) {
  const std::size_t n = v.frame_size();
  const std::size_t step = std::max<std::size_t>(1, n / 4000000);
  std::vector<double> values;
  values.reserve(n / step + 1);
  for (std::size_t i = 0; i < n; i += step)
    if (std::isfinite(v.voxels[i]) && v.voxels[i] != 0) values.push_back(v.voxels[i]);
  if (values.empty()) return {0, 1};
  auto quantile = [&](double q) {
    auto it = values.begin() + static_cast<std::ptrdiff_t>(std::floor(q * double(values.size() - 1)));
    std::nth_element(values.begin(), it, values.end());
    return *it;
  };
  double lo = quantile(0.01), hi = quantile(upper);
  if (hi <= lo) {
    if (lo > 0) lo = 0;
    else hi = lo + 1;
  }
  return {lo, hi};
}

double round_scale_length(double limit_mm) noexcept {
  if (!(limit_mm > 0) || !std::isfinite(limit_mm)) return 0;
  double decade = std::pow(10.0, std::floor(std::log10(limit_mm)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= limit_mm * (1 + 1e-12)) return m * decade;
  return decade / 2;  // not reached: 1 * decade <= limit_mm
}

VolumeView render_volume_view(const Volume& v, const VolumeViewOptions& o) {
  if (v.frame_size() == 0 || v.voxels.size() < v.frame_size()) throw bad_input("the volume has no voxels");
  const bool known = o.orientation_known;
  const CanonicalAxes ax = canonical_axes(v, known);
  VolumeView view;
  view.obliquity_deg = ax.obliquity_deg;
  view.window = o.window ? *o.window : robust_window(v);

  // The slice voxel in canonical order.
  std::array<std::size_t, 3> file_at{v.dims[0] / 2, v.dims[1] / 2, v.dims[2] / 2};
  if (o.slice) {
    file_at = *o.slice;
    for (int a = 0; a < 3; ++a)
      if (file_at[a] >= v.dims[a])
        throw usage_error("slice voxel ({},{},{}) lies outside the volume's {}x{}x{} voxels (indices from 0)", file_at[0],
                          file_at[1], file_at[2], v.dims[0], v.dims[1], v.dims[2]);
  }
  std::array<std::size_t, 3> at{};
  for (int a = 0; a < 3; ++a) {
    const std::size_t f = file_at[ax.src[a]];
    at[a] = ax.flip[a] ? ax.n[a] - 1 - f : f;
  }

  // Display pixel size: the finest spacing, enlarged (integer factor) so that a small
  // volume's largest panel side has about 192 pixels, reduced so that none exceeds 1024.
  double extent = 0, finest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) extent = std::max(extent, double(ax.n[a]) * ax.spacing[a]), finest = std::min(finest, ax.spacing[a]);
  double pixel = o.pixel_mm > 0 ? o.pixel_mm : finest;
  if (o.pixel_mm <= 0) {
    if (extent / pixel < 192) pixel /= std::ceil(192 / (extent / pixel));
    if (extent / pixel > 1024) pixel = extent / 1024;
  }
  view.pixel_mm = pixel;
  Canvas k;
  k.scale = extent / pixel >= 180 ? 2 : 1;

  const char* axis_name = "IJK";
  const bool radiological = o.convention == DisplayConvention::radiological;
  auto slice_title = [&](int fixed, std::size_t c) {
    const std::size_t f = ax.flip[fixed] ? ax.n[fixed] - 1 - c : c;
    return fmt::format("{}={}", axis_name[ax.src[fixed]], f);
  };
  // The three orthogonal panels: axial (R-L across, A up), coronal (R-L across, S up),
  // sagittal (A across, S up).
  const char* names[3] = {"SAGITTAL", "CORONAL", "AXIAL"};  // by fixed axis
  std::vector<PanelSpec> specs;
  for (int fixed : {2, 1, 0}) {
    PanelSpec s;
    s.fixed = fixed;
    s.h = fixed == 0 ? 1 : 0;
    s.v = fixed == 2 ? 1 : 2;
    s.flip_h = radiological && s.h == 0 && known;
    if (o.kind == VolumeViewKind::mip) {
      s.projection = true;
      s.title = known ? fmt::format("MIP {}", names[fixed]) : fmt::format("MIP ALONG {}", axis_name[ax.src[fixed]]);
      specs.push_back(s);
    } else if (o.kind == VolumeViewKind::ortho) {
      s.at = at[fixed];
      s.title = known ? fmt::format("{} {}", names[fixed], slice_title(fixed, s.at)) : slice_title(fixed, s.at);
      specs.push_back(s);
    } else if (fixed == 2) {
      // The slices spread over the axial range with content (empty slices above the head
      // or below the neck waste cells): those where at least 0.5 % of the voxels exceed
      // a tenth of the window; all slices when none does.
      const std::size_t nz = ax.n[2];
      const double level = view.window[0] + 0.1 * (view.window[1] - view.window[0]);
      std::size_t first = nz, last = 0;
      for (std::size_t z = 0; z < nz; ++z) {
        std::size_t above = 0;
        std::array<std::size_t, 3> c{0, 0, z};
        for (c[1] = 0; c[1] < ax.n[1]; ++c[1])
          for (c[0] = 0; c[0] < ax.n[0]; ++c[0]) above += v.voxels[voxel_index(v, ax, c)] > level;
        if (double(above) >= 0.005 * double(ax.n[0] * ax.n[1])) first = std::min(first, z), last = z;
      }
      if (first > last) first = 0, last = nz - 1;
      const std::size_t range = last - first + 1;
      const std::size_t count = std::min<std::size_t>(range, static_cast<std::size_t>(std::max(1, o.montage_slices)));
      for (std::size_t t = 0; t < count; ++t) {
        PanelSpec m = s;
        m.at = first + std::min(range - 1, static_cast<std::size_t>((double(t) + 0.5) * double(range) / double(count)));
        m.title = slice_title(2, m.at);
        specs.push_back(m);
      }
    }
  }

  // Projections gather the brightest voxels: their default window comes from their own
  // values (the 1st to 99.5th percentile of the non-zero ones), not the volume's.
  if (o.kind == VolumeViewKind::mip) {
    Volume sample;
    for (PanelSpec& s : specs) {
      s.mip = projection(v, ax, s);
      sample.voxels.insert(sample.voxels.end(), s.mip.begin(), s.mip.end());
    }
    if (!o.window) {
      sample.dims = {sample.voxels.size(), 1, 1};
      view.window = robust_window(sample, 0.995);
    }
  }
  std::vector<cv::Mat> pixels;
  std::vector<cv::Size> cells;
  for (const PanelSpec& s : specs) {
    pixels.push_back(panel_pixels(v, ax, s, pixel, o, view.window));
    cells.push_back(cell_size(pixels.back(), s.title, k));
  }
  // Grid: one row for ortho and mip, about square for a montage.
  const std::size_t columns =
      o.kind == VolumeViewKind::montage ? static_cast<std::size_t>(std::ceil(std::sqrt(double(specs.size())))) : specs.size();
  const std::size_t rows = (specs.size() + columns - 1) / columns;
  int cell_w = 0, cell_h = 0;  // montage cells share one size
  for (const cv::Size& c : cells) cell_w = std::max(cell_w, c.width), cell_h = std::max(cell_h, c.height);
  int grid_w = 0;
  if (o.kind == VolumeViewKind::montage)
    grid_w = cell_w * static_cast<int>(columns);
  else
    for (const cv::Size& c : cells) grid_w += c.width;
  const int grid_h = cell_h * static_cast<int>(rows);

  // Scale bar: a round length at most 0.3 of the narrowest panel's width.
  double narrowest = std::numeric_limits<double>::infinity();
  for (const cv::Mat& p : pixels) narrowest = std::min(narrowest, double(p.cols) * pixel);
  view.scale_bar_mm = round_scale_length(0.3 * narrowest);
  view.scale_bar_px = std::max(1, static_cast<int>(std::lround(view.scale_bar_mm / pixel)));
  const std::string bar_label = number_text(view.scale_bar_mm) + " mm";
  std::string info;
  if (!known)
    info = "ORIENTATION UNKNOWN";
  else
    info = radiological ? "RADIOLOGICAL: R ON LEFT" : "NEUROLOGICAL: L ON LEFT";
  if (known && ax.obliquity_deg > 0.5) view.note = fmt::format("OBLIQUE {:.0f} DEG: NEAREST AXES", ax.obliquity_deg);
  if (!known) view.note = "orientation unknown";
  const std::string window_text = fmt::format("WINDOW {} TO {}", number_text(view.window[0]), number_text(view.window[1]));
  const std::string info_line = info + "   " + window_text;
  const int footer_lines = view.note.empty() || !known ? 2 : 3;
  const int footer_w =
      std::max({view.scale_bar_px + text_width(bar_label, k.scale) + 4 * k.pad(), text_width(info_line, k.scale) + 2 * k.pad(),
                known ? text_width(view.note, k.scale) + 2 * k.pad() : 0});
  const int width = std::max(grid_w, footer_w);
  const int height = grid_h + footer_lines * k.line();
  view.rgb = cv::Mat(height, width, CV_8UC3, cv::Scalar(0, 0, 0));

  int x = 0;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    int cx = x, cy = 0;
    cv::Size cell = cells[i];
    if (o.kind == VolumeViewKind::montage) {
      cx = static_cast<int>(i % columns) * cell_w, cy = static_cast<int>(i / columns) * cell_h;
      cell = {cell_w, cells[i].height};
    }
    view.panels.push_back(draw_cell(view.rgb, cx, cy, cell, pixels[i], specs[i], ax, known, k));
    x += cell.width;
  }
  // Footer: the scale bar with its length, the convention (or "orientation unknown"),
  // the window, and a note on obliquity.
  int y = grid_h + k.pad();
  const int bar_y = y + text_height(k.scale) / 2 - k.scale;
  fill_rect(view.rgb, k.pad(), bar_y, view.scale_bar_px, 2 * k.scale, kBarColour);
  fill_rect(view.rgb, k.pad(), bar_y - 2 * k.scale, k.scale, 6 * k.scale, kBarColour);
  fill_rect(view.rgb, k.pad() + view.scale_bar_px - k.scale, bar_y - 2 * k.scale, k.scale, 6 * k.scale, kBarColour);
  draw_text(view.rgb, 3 * k.pad() + view.scale_bar_px, y, bar_label, kTextColour, k.scale);
  y += k.line();
  draw_text(view.rgb, k.pad(), y, info_line, kTextColour, k.scale);
  if (known && !view.note.empty()) draw_text(view.rgb, k.pad(), y + k.line(), view.note, kLetterColour, k.scale);
  return view;
}

}  // namespace fest
