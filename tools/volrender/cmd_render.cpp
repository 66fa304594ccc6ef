// volrender dvr|mip|minip|avg|iso: read a volume, build the transfer function and the
// camera(s), ray cast (lib/raycast), write images (docs/volrender.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "camera_args.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/srgb.hpp"
#include "core/threads.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "raycast/mesh_tracer.hpp"
#include "raycast/render.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

namespace fest::volrender {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Loaded {
  volume_pyramid::ScalarGrid grid;
  double lo = 0, hi = 1;
  std::string name;
};

Loaded load(const RenderArgs& a) {
  Loaded L;
  L.name = a.input == "-" ? "stdin" : a.input;
  formats::Input in = formats::load_input(a.input);
  if (in.bytes.empty()) throw bad_input("empty input ({})", L.name);
  formats::VolumeSourceOptions vo;
  vo.field = a.field, vo.component = a.component, vo.frame = a.frame;
  const Volume v = formats::read_volume_source(in, vo);
  for (int ax = 0; ax < 3; ++ax)
    if (v.dims[ax] < 2) throw bad_input("volume is {}x{}x{}: ray casting needs 2 samples along every axis ({})", v.dims[0], v.dims[1], v.dims[2], L.name);
  std::size_t nans = 0;
  L.grid = volume_pyramid::to_grid(v, nans);
  if (nans) throw bad_input("{} NaN samples ({})", nans, L.name);
  float lo = L.grid.values[0], hi = lo;
  for (float x : L.grid.values) lo = std::min(lo, x), hi = std::max(hi, x);
  L.lo = lo, L.hi = hi;
  return L;
}

raycast::TransferFunction make_tf(const RenderArgs& a, const Loaded& L) {
  const auto mode = a.tf_mode == "extinction" ? raycast::OpacityMode::extinction : raycast::OpacityMode::opacity;
  if (a.tf_mode != "extinction" && a.tf_mode != "opacity") throw usage_error("--tf-mode must be opacity or extinction");
  if (!(a.tf_unit > 0)) throw usage_error("--tf-unit must be positive");
  std::vector<raycast::ControlPoint> pts;
  const std::string name = a.tf.empty() ? (a.mode == "slices" ? "contour-only" : "grey") : a.tf;
  try {
    if (raycast::is_preset(name)) {
      pts = raycast::preset_transfer_function(name, L.lo, L.hi);
    } else {
      const std::string text = read_input(name);
      pts = raycast::parse_transfer_function(text, L.lo, L.hi, mode);
    }
  } catch (const std::invalid_argument& e) {
    throw bad_input("{} ({})", e.what(), name);
  }
  return raycast::TransferFunction(pts, L.lo, L.hi, mode, a.tf_unit);
}

std::vector<raycast::IsoLayer> parse_isos(const std::string& s, const std::string& colors) {
  std::vector<raycast::IsoLayer> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) {
    raycast::IsoLayer L;
    const auto colon = item.find(':');
    char* end = nullptr;
    const std::string v = item.substr(0, colon);
    L.value = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(L.value)) throw usage_error("--iso takes V[:alpha][,V:alpha...], not '{}'", s);
    if (colon != std::string::npos) {
      const std::string al = item.substr(colon + 1);
      L.alpha = std::strtod(al.c_str(), &end);
      if (al.empty() || *end || !(L.alpha >= 0 && L.alpha <= 1)) throw usage_error("--iso opacity must be in [0,1] ('{}')", item);
    }
    out.push_back(L);
  }
  if (!colors.empty()) {
    std::stringstream cs(colors);
    std::size_t k = 0;
    for (std::string item; std::getline(cs, item, ';'); ++k) {
      if (k >= out.size()) throw usage_error("--iso-color names more colours than iso-values");
      const auto c = parse_numbers(item, 3, 3, "--iso-color");
      out[k].color = std::array<double, 3>{c[0], c[1], c[2]};
    }
  }
  return out;
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
  const auto c = parse_numbers(a.mesh_color, 3, 3, "--mesh-color");
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

}  // namespace

int run_render(const RenderArgs& a) {
  raycast::RenderOptions o;
  if (a.mode == "dvr") o.mode = raycast::Mode::dvr;
  else if (a.mode == "mip") o.mode = raycast::Mode::mip;
  else if (a.mode == "minip") o.mode = raycast::Mode::minip;
  else if (a.mode == "avg") o.mode = raycast::Mode::avg;
  else if (a.mode == "iso") o.mode = raycast::Mode::iso;
  else if (a.mode == "slices") o.mode = raycast::Mode::slices;
  else throw usage_error("unknown mode '{}'", a.mode);
  if (o.mode == raycast::Mode::iso && a.iso.empty()) throw usage_error("iso mode needs --iso V[:alpha][,...]");
  if (!(a.step > 0 && a.step <= 64)) throw usage_error("--step must be in (0, 64]");
  if (!(a.ert > 0 && a.ert <= 1)) throw usage_error("--ert must be in (0, 1]");
  if (a.interp != "trilinear" && a.interp != "nearest") throw usage_error("--interp must be trilinear or nearest");
  if (a.shade != "on" && a.shade != "off") throw usage_error("--shade must be on or off");
  const std::string fmt = output_format(a.to, a.output);
  const bool stereo = a.camera.stereo.has_value();
  const std::string layout = a.camera.stereo_layout;
  if (stereo && layout != "files" && layout != "sbs" && layout != "tb" && layout != "anaglyph")
    throw usage_error("--stereo-layout must be files, sbs, tb or anaglyph");
  if (stereo && layout == "files" && a.output.find("%s") == std::string::npos)
    throw usage_error("--stereo with the files layout needs an output pattern with %s (L and R)");
  o.step = a.step, o.jitter = a.jitter, o.nearest = a.interp == "nearest", o.shade = a.shade == "on";
  const auto ph = parse_numbers(a.phong, 4, 4, "--phong");
  o.phong = {ph[0], ph[1], ph[2], ph[3]};
  o.two_sided = a.two_sided, o.ert = a.ert, o.preint = a.preint, o.spp = a.spp, o.skip_empty = !a.no_skip;
  o.threads = resolve_threads(a.threads);
  if (a.bg == "none") o.keep_alpha = true;
  else {
    const auto bg = parse_numbers(a.bg, 3, 4, "--bg");
    o.background = {bg[0], bg[1], bg[2]};
  }
  if (!a.window.empty()) {
    const auto w = parse_numbers(a.window, 2, 2, "--window");
    if (!(w[1] > w[0])) throw usage_error("--window lo,hi needs lo < hi");
    o.window = std::array<double, 2>{w[0], w[1]};
  }
  if (!a.iso.empty()) o.isos = parse_isos(a.iso, a.iso_color);

  auto t0 = Clock::now();
  const Loaded L = load(a);
  const double t_read = seconds_since(t0);
  const auto tf = make_tf(a, L);
  const auto cams = make_cameras(a.camera, &L.grid);
  if (o.mode == raycast::Mode::slices) {
    if (a.contours.empty()) throw usage_error("slices mode needs --contours c0:dc:n");
    std::string c = a.contours;
    std::replace(c.begin(), c.end(), ':', ',');
    const auto v = parse_numbers(c, 3, 3, "--contours");
    if (!(v[1] > 0) || v[2] < 1 || v[2] != std::floor(v[2])) throw usage_error("--contours c0:dc:n needs dc > 0 and a whole n >= 1");
    if (!(a.contour_width > 0)) throw usage_error("--contour-width must be positive");
    if (a.contour_width_world && !(*a.contour_width_world > 0 && std::isfinite(*a.contour_width_world)))
      throw usage_error("--contour-width-world must be positive");
    raycast::SliceStack& S = o.slices;
    S.c0 = v[0], S.dc = v[1], S.count = static_cast<int>(v[2]);
    S.width = a.contour_width, S.contour_alpha = a.contour_alpha, S.tf_unit = a.tf_unit;
    S.width_world = a.contour_width_world.value_or(0.0);
    if (a.slice_frame) {  // one smallest spacing wide
      double h = INFINITY;
      for (int ax = 0; ax < 3; ++ax)
        h = std::min(h, std::sqrt(L.grid.axes[ax] * L.grid.axes[ax] + L.grid.axes[3 + ax] * L.grid.axes[3 + ax] + L.grid.axes[6 + ax] * L.grid.axes[6 + ax]));
      S.frame_width = h;
    }
    const auto& g = L.grid;
    if (a.slice_axis == "x" || a.slice_axis == "y" || a.slice_axis == "z") {
      const int ax = a.slice_axis[0] - 'x';
      S.normal = raycast::normalized(raycast::Vec3{g.axes[ax], g.axes[3 + ax], g.axes[6 + ax]});
    } else {
      const auto n = parse_numbers(a.slice_axis, 3, 3, "--slice-axis");
      if (raycast::norm(raycast::Vec3{n[0], n[1], n[2]}) == 0) throw usage_error("--slice-axis normal has zero length");
      S.normal = raycast::normalized(raycast::Vec3{n[0], n[1], n[2]});
    }
    if (!a.slice_at.empty()) {
      S.offsets = parse_numbers(a.slice_at, 1, 4096, "--slice-at");
    } else {
      double lo = INFINITY, hi = -INFINITY;
      for (int q = 0; q < 8; ++q) {
        const auto w = g.world(q & 1 ? g.dims[0] - 1.0 : 0.0, q & 2 ? g.dims[1] - 1.0 : 0.0, q & 4 ? g.dims[2] - 1.0 : 0.0);
        const double p = raycast::dot(S.normal, raycast::Vec3{w[0], w[1], w[2]});
        lo = std::min(lo, p), hi = std::max(hi, p);
      }
      for (int k = 0; k < a.slice_count; ++k) S.offsets.push_back(lo + (k + 0.5) * (hi - lo) / a.slice_count);
    }
  }
  o.gradient_cache = a.gradients == "cache" || (a.gradients == "auto" && L.grid.size() <= (std::size_t{64} << 20));
  t0 = Clock::now();
  // Finest level 2 (4^3 cells): skipping blocks fit the skin and bone of a CT closer than
  // 8^3 blocks (docs/volrender.md "Acceleration"); the shading volume is built once for
  // every image (both eyes of a stereo pair).
  const volume_pyramid::MinMaxPyramid pyramid(L.grid, o.threads, 2);
  raycast::ShadingVolume shading;
  if (o.shade && o.gradient_cache) shading = raycast::shading_volume(L.grid, o.threads);
  const double t_build = seconds_since(t0);
  t0 = Clock::now();
  std::vector<raycast::RenderedImage> images;
  const auto mesh = load_mesh(a);
  for (const auto& c : cams)
    images.push_back(raycast::render(L.grid, &pyramid, tf, c, o, mesh ? &raycast::MeshTracer::callback : nullptr,
                                     mesh ? &*mesh : nullptr, shading.data ? &shading : nullptr));
  const double t_render = seconds_since(t0);
  t0 = Clock::now();
  if (stereo && layout == "files") {
    for (int e = 0; e < 2; ++e) {
      std::string path = a.output;
      path.replace(path.find("%s"), 2, e ? "R" : "L");
      write_output(path, encode(images[e], fmt, o.keep_alpha, a.linear));
    }
  } else {
    const raycast::RenderedImage img = stereo ? combine(images[0], images[1], layout) : images[0];
    if (!a.depth_image.empty()) write_output(a.depth_image, encode_depth(img));
    write_output(a.output, encode(img, fmt, o.keep_alpha, a.linear));
  }
  const double t_write = seconds_since(t0);
  if (!a.camera_json.empty()) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& c : cams) j.push_back(camera_json(c));
    write_output(a.camera_json, j.dump(2) + "\n");
  }
  if (!a.report.empty()) {
    raycast::RenderStats s;
    for (const auto& im : images) s.rays += im.stats.rays, s.samples += im.stats.samples, s.skipped += im.stats.skipped, s.terminated += im.stats.terminated;
    nlohmann::json j = {{"mode", a.mode},
                        {"rays", s.rays},
                        {"samples", s.samples},
                        {"samples_skipped", s.skipped},
                        {"rays_terminated", s.terminated},
                        {"pyramid_bytes", pyramid.bytes()},
                        {"time_s", {{"read", t_read}, {"build", t_build}, {"render", t_render}, {"write", t_write}}}};
    write_output(a.report, j.dump(2) + "\n");
  }
  return 0;
}

int run_camera_print(const CameraPrintArgs& a) {
  std::vector<raycast::Camera> cams;
  if (!a.input.empty()) {
    RenderArgs ra;
    ra.input = a.input;
    const Loaded L = load(ra);
    cams = make_cameras(a.camera, &L.grid);
  } else {
    cams = make_cameras(a.camera, nullptr);
  }
  nlohmann::json j = nlohmann::json::array();
  for (const auto& c : cams) j.push_back(camera_json(c));
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace fest::volrender
