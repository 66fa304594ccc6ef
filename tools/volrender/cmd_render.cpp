// volrender dvr|mip|minip|avg|iso|slices: read a volume (or every frame of a stream or
// series), build the transfer function and the camera(s), ray cast (lib/raycast), write
// images (docs/volrender.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "camera_args.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/progress.hpp"
#include "core/srgb.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "image_pixels.hpp"
#include "raycast/mesh_tracer.hpp"
#include "raycast/render.hpp"
#include "volume_input.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

namespace fest::volrender_tool {
namespace {

using Clock = SteadyClock;

const char* mode_name(raycast::Mode m) {
  switch (m) {
    case raycast::Mode::dvr: return "dvr";
    case raycast::Mode::mip: return "mip";
    case raycast::Mode::minip: return "minip";
    case raycast::Mode::avg: return "avg";
    case raycast::Mode::iso: return "iso";
    case raycast::Mode::slices: return "slices";
  }
  return "?";
}

raycast::TransferFunction make_tf(const RenderArgs& a, double lo, double hi) {
  if (!(a.tf_unit > 0)) throw usage_error("--tf-unit must be positive");
  std::vector<raycast::ControlPoint> pts;
  const std::string name = a.tf.empty() ? (a.mode == raycast::Mode::slices ? "contour-only" : "grey") : a.tf;
  try {
    if (raycast::is_preset(name)) {
      pts = raycast::preset_transfer_function(name, lo, hi);
    } else {
      const std::string text = read_input(name);
      pts = raycast::parse_transfer_function(text, lo, hi, a.tf_mode);
    }
  } catch (const std::invalid_argument& e) {
    throw bad_input("{} ({})", e.what(), name);
  }
  return raycast::TransferFunction(pts, lo, hi, a.tf_mode, a.tf_unit);
}

std::string output_format(const std::string& to, const std::string& out) {
  std::string f = to;
  if (f.empty() && out != "-") {
    const auto dot = out.rfind('.');
    if (dot != std::string::npos) f = out.substr(dot + 1);
  }
  if (f.empty()) f = "png";
  if (f != "png" && f != "pfm" && f != "exr") throw usage_error("image format '{}' (png, pfm or exr expected)", f);
  return f;
}

// The position and width of the one printf-style %d (%05d, %4d, ...) in an output pattern
// of --frame all; npos when there is none.
std::size_t frame_field(const std::string& pattern, std::size_t& length, int& width, bool& zero) {
  std::size_t found = std::string::npos;
  for (std::size_t p = pattern.find('%'); p != std::string::npos; p = pattern.find('%', p + 1)) {
    std::size_t q = p + 1;
    const bool z = q < pattern.size() && pattern[q] == '0';
    int w = 0;
    while (q < pattern.size() && pattern[q] >= '0' && pattern[q] <= '9' && w < 100) w = 10 * w + (pattern[q++] - '0');
    if (q < pattern.size() && pattern[q] == 'd') {
      if (found != std::string::npos) throw usage_error("output pattern '{}' has more than one %d", pattern);
      found = p, length = q + 1 - p, width = w, zero = z;
    }
  }
  return found;
}

// The pattern with its %d replaced by the frame number (--frame all).
std::string frame_path(const std::string& pattern, std::size_t frame) {
  std::size_t length = 0;
  int width = 0;
  bool zero = false;
  const std::size_t at = frame_field(pattern, length, width, zero);
  if (at == std::string::npos) throw usage_error("--frame all writes one image per frame: '{}' needs a %d (e.g. png/%05d.png)", pattern);
  std::string number = std::to_string(frame);
  if (static_cast<int>(number.size()) < width) number.insert(0, static_cast<std::size_t>(width) - number.size(), zero ? '0' : ' ');
  return pattern.substr(0, at) + number + pattern.substr(at + length);
}

// --screen-mask: cast the pixels whose mask pixel is neither black nor transparent.
std::vector<std::uint8_t> screen_mask(const std::string& path, int width, int height) {
  const Image im = load_image(path);
  if (im.pixels.cols != width || im.pixels.rows != height)
    throw bad_input("screen mask is {}x{}, the image {}x{} ({})", im.pixels.cols, im.pixels.rows, width, height, path);
  const auto px = linear_rgba(im, path);
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * height);
  for (std::size_t p = 0; p < mask.size(); ++p)
    mask[p] = px[4 * p + 3] > 0 && (px[4 * p] > 0 || px[4 * p + 1] > 0 || px[4 * p + 2] > 0);
  return mask;
}

// The planes of the slices mode for this volume (docs/volrender.md section 3).
raycast::SliceStack slice_stack(const RenderArgs& a, const volume_pyramid::ScalarGrid& g) {
  if (!a.contours) throw usage_error("slices mode needs --contours c0:dc:n");
  const Contours& v = *a.contours;
  if (!(v.dc > 0) || v.count < 1 || v.count != std::floor(v.count)) throw usage_error("--contours c0:dc:n needs dc > 0 and a whole n >= 1");
  if (!(a.contour_width > 0)) throw usage_error("--contour-width must be positive");
  if (a.contour_width_world && !(*a.contour_width_world > 0 && std::isfinite(*a.contour_width_world)))
    throw usage_error("--contour-width-world must be positive");
  raycast::SliceStack S;
  S.c0 = v.c0, S.dc = v.dc, S.count = static_cast<int>(v.count);
  S.width = a.contour_width, S.contour_alpha = a.contour_alpha, S.tf_unit = a.tf_unit;
  S.width_world = a.contour_width_world.value_or(0.0);
  if (a.slice_frame) {  // one smallest spacing wide
    double h = INFINITY;
    for (int ax = 0; ax < 3; ++ax)
      h = std::min(h, std::sqrt(g.axes[ax] * g.axes[ax] + g.axes[3 + ax] * g.axes[3 + ax] + g.axes[6 + ax] * g.axes[6 + ax]));
    S.frame_width = h;
  }
  if (!a.slice_axis.normal) {
    const int ax = a.slice_axis.index_axis;
    S.normal = raycast::normalized(raycast::Vec3{g.axes[ax], g.axes[3 + ax], g.axes[6 + ax]});
  } else {
    const raycast::Vec3 n = *a.slice_axis.normal;
    if (raycast::norm(n) == 0) throw usage_error("--slice-axis normal has zero length");
    S.normal = raycast::normalized(n);
  }
  if (!a.slice_at.empty()) {
    S.offsets = a.slice_at;
  } else {
    double lo = INFINITY, hi = -INFINITY;
    for (int q = 0; q < 8; ++q) {
      const auto w = g.world(q & 1 ? g.dims[0] - 1.0 : 0.0, q & 2 ? g.dims[1] - 1.0 : 0.0, q & 4 ? g.dims[2] - 1.0 : 0.0);
      const double p = raycast::dot(S.normal, raycast::Vec3{w[0], w[1], w[2]});
      lo = std::min(lo, p), hi = std::max(hi, p);
    }
    for (int k = 0; k < a.slice_count; ++k) S.offsets.push_back(lo + (k + 0.5) * (hi - lo) / a.slice_count);
  }
  return S;
}

// Linear float RGBA -> the file's bytes.
std::string encode(const raycast::RenderedImage& img, const std::string& fmt, bool keep_alpha, bool linear) {
  const int ch = keep_alpha ? 4 : 3;
  Image out;
  if (fmt == "png") {
    out.pixels.create(img.height, img.width, CV_8UC(ch));
    out.color_space = ColorSpace::srgb;
    for (int j = 0; j < img.height; ++j)
      for (int i = 0; i < img.width; ++i) {
        const float* p = &img.rgba[(static_cast<std::size_t>(j) * img.width + i) * 4];
        auto* q = out.pixels.ptr<unsigned char>(j) + i * ch;
        for (int c = 0; c < 3; ++c) q[c] = static_cast<unsigned char>(std::lround(255.0 * (linear ? std::clamp(double(p[c]), 0.0, 1.0) : linear_to_srgb(p[c]))));
        if (ch == 4) q[3] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(double(p[3]), 0.0, 1.0)));
      }
    return formats::write_image(out, formats::Format::png);
  }
  const int fch = fmt == "pfm" ? 3 : ch;
  out.pixels.create(img.height, img.width, CV_32FC(fch));
  out.color_space = ColorSpace::linear;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const float* p = &img.rgba[(static_cast<std::size_t>(j) * img.width + i) * 4];
      float* q = out.pixels.ptr<float>(j) + i * fch;
      for (int c = 0; c < fch; ++c) q[c] = p[c];
    }
  return formats::write_image(out, fmt == "pfm" ? formats::Format::pfm : formats::Format::exr);
}

std::string encode_depth(const raycast::RenderedImage& img) {
  Image d;
  d.pixels.create(img.height, img.width, CV_32FC1);
  d.color_space = ColorSpace::linear;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) d.pixels.ptr<float>(j)[i] = img.depth[static_cast<std::size_t>(j) * img.width + i];
  return formats::write_image(d, formats::Format::pfm);
}

// Side by side / top-bottom / red-cyan anaglyph of a stereo pair.
raycast::RenderedImage combine(const raycast::RenderedImage& L, const raycast::RenderedImage& R, const std::string& layout) {
  raycast::RenderedImage out;
  if (layout == "anaglyph") {
    out = L;
    for (std::size_t p = 0; p < L.rgba.size() / 4; ++p) {
      out.rgba[4 * p + 0] = 0.299f * L.rgba[4 * p] + 0.587f * L.rgba[4 * p + 1] + 0.114f * L.rgba[4 * p + 2];
      out.rgba[4 * p + 1] = R.rgba[4 * p + 1];
      out.rgba[4 * p + 2] = R.rgba[4 * p + 2];
    }
    return out;
  }
  const bool sbs = layout == "sbs";
  out.width = sbs ? 2 * L.width : L.width;
  out.height = sbs ? L.height : 2 * L.height;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  out.depth.resize(static_cast<std::size_t>(out.width) * out.height);
  for (int j = 0; j < L.height; ++j)
    for (int i = 0; i < L.width; ++i)
      for (int e = 0; e < 2; ++e) {
        const auto& S = e ? R : L;
        const int x = sbs ? i + e * L.width : i, y = sbs ? j : j + e * L.height;
        const std::size_t src = static_cast<std::size_t>(j) * L.width + i, dst = static_cast<std::size_t>(y) * out.width + x;
        for (int c = 0; c < 4; ++c) out.rgba[4 * dst + c] = S.rgba[4 * src + c];
        out.depth[dst] = S.depth[src];
      }
  return out;
}

// The mesh of --mesh: triangles, quads split in two; larger polygons are refused.
std::optional<raycast::MeshTracer> load_mesh(const RenderArgs& a) {
  if (a.mesh.empty()) return std::nullopt;
  const auto& c = a.mesh_color;
  formats::Input in = formats::load_input(a.mesh);
  if (in.bytes.empty()) throw bad_input("empty mesh ({})", a.mesh);
  if (formats::kind_of(in.format) != formats::Kind::mesh) throw bad_input("--mesh expects a mesh, got {} ({})", formats::format_name(in.format), a.mesh);
  const Mesh m = formats::parse(in, formats::read_mesh);
  std::vector<float> xyz;
  for (const auto& v : m.vertices())
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(m.point(v)[k]));
  std::vector<std::array<std::uint32_t, 3>> tris;
  std::size_t big = 0;
  auto add = [&](const std::vector<std::uint32_t>& p) {
    if (p.size() > 4) return void(++big);
    for (std::size_t k = 1; k + 1 < p.size(); ++k) tris.push_back({p[0], p[k], p[k + 1]});
  };
  std::vector<std::uint32_t> poly;
  for (const auto& f : m.faces()) {
    poly.clear();
    for (const auto& v : m.fv_range(f)) poly.push_back(static_cast<std::uint32_t>(v.idx()));
    add(poly);
  }
  for (const auto& f : formats::skipped_face_list(m)) add(std::vector<std::uint32_t>(f.begin(), f.end()));
  if (big) throw bad_input("{} faces of the mesh have more than 4 vertices; triangulate it first ({})", big, a.mesh);
  return raycast::MeshTracer(std::move(xyz), std::move(tris), {c[0], c[1], c[2]});
}

// What every image of a run shares: options checked, output format, the mesh.
struct RenderSetup {
  raycast::RenderOptions options;
  std::string format;
  std::optional<raycast::MeshTracer> mesh;
  // --progress: every image (frame, eye) is 1000 steps of images x 1000.
  Progress* bar = nullptr;
  std::uint64_t images = 1, image = 0;
};

RenderSetup setup(const RenderArgs& a) {
  RenderSetup S;
  raycast::RenderOptions& o = S.options;
  o.mode = a.mode;
  if (o.mode == raycast::Mode::iso && a.isos.empty()) throw usage_error("iso mode needs --iso V[:alpha][,...]");
  if (!(a.step > 0 && a.step <= 64)) throw usage_error("--step must be in (0, 64]");
  if (!(a.ert > 0 && a.ert <= 1)) throw usage_error("--ert must be in (0, 1]");
  S.format = output_format(a.to, a.output);
  const bool stereo = a.camera.stereo.has_value();
  if (stereo && a.camera.stereo_layout == StereoLayout::files && a.output.find("%s") == std::string::npos)
    throw usage_error("--stereo with the files layout needs an output pattern with %s (L and R)");
  if (a.all_frames) {
    if (a.output == "-") throw usage_error("--frame all writes one image per frame: give -o with %d (e.g. png/%05d.png)");
    frame_path(a.output, 0);
    if (!a.depth_image.empty()) frame_path(a.depth_image, 0);
  }
  o.step = a.step, o.jitter = a.jitter, o.nearest = a.nearest, o.shade = a.shade;
  o.phong = a.phong;
  o.two_sided = a.two_sided, o.ert = a.ert, o.preint = a.preint, o.spp = a.spp, o.skip_empty = !a.no_skip;
  o.threads = resolve_threads(a.threads);
  o.keep_alpha = a.keep_alpha;
  if (!a.keep_alpha) o.background = a.background;
  if (a.window) {
    const auto& w = *a.window;
    if (!(w[1] > w[0])) throw usage_error("--window lo,hi needs lo < hi");
    o.window = w;
  }
  o.isos = a.isos;
  return S;
}

struct FrameResult {
  std::vector<raycast::Camera> cameras;
  std::vector<raycast::RenderedImage> images;
  double t_build = 0, t_render = 0;
  std::size_t pyramid_bytes = 0;
};

// The image(s) of one volume: one, or a stereo pair.
FrameResult render_volume(const RenderArgs& a, RenderSetup& S, const LoadedVolume& L, const raycast::TransferFunction& tf) {
  FrameResult F;
  raycast::RenderOptions& o = S.options;
  F.cameras = make_cameras(a.camera, &L.grid);
  if (o.mode == raycast::Mode::slices) o.slices = slice_stack(a, L.grid);
  o.gradient_cache = a.gradients == Gradients::cache || (a.gradients == Gradients::automatic && L.grid.size() <= (std::size_t{64} << 20));
  auto t0 = Clock::now();
  // Finest level 2 (4^3 cells): skipping blocks fit the skin and bone of a CT closer than
  // 8^3 blocks (docs/volrender.md "Acceleration"); the shading volume is built once for
  // every image (both eyes of a stereo pair).
  const volume_pyramid::MinMaxPyramid pyramid(L.grid, o.threads, 2);
  raycast::ShadingVolume shading;
  if (o.shade && o.gradient_cache) shading = raycast::shading_volume(L.grid, o.threads);
  F.t_build = seconds_since(t0);
  F.pyramid_bytes = pyramid.bytes();
  t0 = Clock::now();
  if (!a.mesh.empty() && !S.mesh) S.mesh = load_mesh(a);
  const auto* mesh = S.mesh ? &*S.mesh : nullptr;
  for (const auto& c : F.cameras) {
    if (S.bar)
      o.progress = [&S](std::uint64_t done, std::uint64_t total) {
        S.bar->set(S.image * 1000 + (total ? done * 1000 / total : 0), S.images * 1000);
      };
    F.images.push_back(raycast::render(L.grid, &pyramid, tf, c, o, mesh ? &raycast::MeshTracer::callback : nullptr, mesh,
                                       shading.built() ? &shading : nullptr));
    ++S.image;
  }
  F.t_render = seconds_since(t0);
  return F;
}

// Writes the image(s) of one volume to `output` (and `depth`; "" = none).
void write_images(const RenderArgs& a, const RenderSetup& S, const FrameResult& F, const std::string& output, const std::string& depth) {
  const bool stereo = a.camera.stereo.has_value();
  if (stereo && a.camera.stereo_layout == StereoLayout::files) {
    for (int e = 0; e < 2; ++e) {
      std::string path = output;
      path.replace(path.find("%s"), 2, e ? "R" : "L");
      write_output(path, encode(F.images[static_cast<std::size_t>(e)], S.format, S.options.keep_alpha, a.linear));
    }
  } else {
    const char* layout = a.camera.stereo_layout == StereoLayout::sbs ? "sbs" : a.camera.stereo_layout == StereoLayout::tb ? "tb" : "anaglyph";
    const raycast::RenderedImage img = stereo ? combine(F.images[0], F.images[1], layout) : F.images[0];
    if (!depth.empty()) write_output(depth, encode_depth(img));
    write_output(output, encode(img, S.format, S.options.keep_alpha, a.linear));
  }
}

}  // namespace

int run_render(const RenderArgs& a) {
  RenderSetup S = setup(a);
  if (!a.screen_mask.empty()) S.options.pixel_mask = screen_mask(a.screen_mask, a.camera.width, a.camera.height);
  if (!a.screen_polygon.empty()) S.options.pixel_mask = raycast::polygon_pixel_mask(a.screen_polygon, a.camera.width, a.camera.height);
  formats::VolumeSourceOptions vo;
  vo.field = a.field, vo.component = a.component, vo.frame = a.frame, vo.raw = a.raw;

  auto t0 = Clock::now();
  raycast::RenderStats stats;
  double t_read = 0, t_build = 0, t_render = 0, t_write = 0;
  std::size_t pyramid_bytes = 0, frame_count = 1;
  std::vector<raycast::Camera> cameras;
  Progress bar("volrender", 0, progress_wanted(a.progress));
  S.bar = &bar;
  const std::uint64_t eyes = a.camera.stereo.has_value() ? 2 : 1;
  S.images = eyes;
  auto account = [&](const FrameResult& F) {
    for (const auto& im : F.images)
      stats.rays += im.stats.rays, stats.samples += im.stats.samples, stats.skipped += im.stats.skipped, stats.terminated += im.stats.terminated;
    t_build += F.t_build, t_render += F.t_render;
    pyramid_bytes = std::max(pyramid_bytes, F.pyramid_bytes);
    if (cameras.empty()) cameras = F.cameras;
  };
  if (!a.all_frames) {
    const LoadedVolume L = load_volume(a.input, vo);
    t_read = seconds_since(t0);
    const auto tf = make_tf(a, L.lo, L.hi);
    const FrameResult F = render_volume(a, S, L, tf);
    account(F);
    t0 = Clock::now();
    write_images(a, S, F, a.output, a.depth_image);
    t_write = seconds_since(t0);
  } else {
    // Every frame, one image (or pair) each. A first pass checks every frame and finds the
    // value range over all of them, so that nothing is written for a bad frame and a preset
    // or %-valued transfer function maps a value to the same colour in every frame.
    const std::string name = input_name(a.input);
    const formats::Input in = formats::load_volume_input(a.input, vo);
    if (in.bytes.empty()) throw bad_input("empty input ({})", name);
    vo.frame = -1;
    const formats::VolumeFrames frames(in, vo);
    frame_count = frames.count();
    S.images = eyes * frame_count;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t t = 0; t < frame_count; ++t) {
      const LoadedVolume L = load_frame(frames, t, name);
      lo = std::min(lo, L.lo), hi = std::max(hi, L.hi);
    }
    t_read = seconds_since(t0);
    const auto tf = make_tf(a, lo, hi);
    for (std::size_t t = 0; t < frame_count; ++t) {
      t0 = Clock::now();
      const LoadedVolume L = load_frame(frames, t, name);
      t_read += seconds_since(t0);
      const FrameResult F = render_volume(a, S, L, tf);
      account(F);
      t0 = Clock::now();
      write_images(a, S, F, frame_path(a.output, t), a.depth_image.empty() ? "" : frame_path(a.depth_image, t));
      t_write += seconds_since(t0);
    }
  }
  bar.finish();
  if (!a.camera_json.empty()) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& c : cameras) j.push_back(camera_json(c));
    write_output(a.camera_json, j.dump(2) + "\n");
  }
  if (!a.report.empty()) {
    nlohmann::json j = {{"mode", mode_name(a.mode)},
                        {"rays", stats.rays},
                        {"samples", stats.samples},
                        {"samples_skipped", stats.skipped},
                        {"rays_terminated", stats.terminated},
                        {"pyramid_bytes", pyramid_bytes},
                        {"time_s", {{"read", t_read}, {"build", t_build}, {"render", t_render}, {"write", t_write}}}};
    if (a.all_frames) j["frames"] = frame_count;
    write_output(a.report, j.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::volrender_tool
