// volrender: headless CPU volume ray casting (DVR, MIP, MinIP, average, iso) with orbit,
// look-at, off-axis, stereo and beam-splitter-mirror cameras (docs/volrender.md). Flags
// only, parsed into the typed options of commands.hpp; the work is in cmd_*.cpp.

#include <filesystem>
#include <limits>
#include <stdexcept>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/number_list.hpp"
#include "commands.hpp"

namespace {

using namespace fest::volrender_tool;
using fest::cli::number_list;
using fest::raycast::Vec3;

// The text of the flags that become numbers, vectors and lists once CLI11 has parsed.
struct CameraText {
  std::string size = "512x512", view = "0,0", eye, look_at, up = "0,0,1", screen, mirror, mirror_poly, head_right;
};
struct RenderText {
  std::string frame, raw, raw_spacing, bg = "0,0,0", phong = "0.3,0.7,0.2,20", window, iso, iso_color;
  std::string slice_axis = "z", slice_at, contours, mesh_color = "0.9,0.85,0.75", screen_mask;
};

void add_camera(CLI::App* s, CameraArgs& c, CameraText& t) {
  s->add_option("--size", t.size, "Image size WxH")->default_val("512x512");
  s->add_option("--view", t.view, "Orbit camera: AZ,EL[,ROLL] degrees around the volume centre (0,0 looks along +y, z up)");
  s->add_option("--zoom", c.zoom, "Orbit camera magnification");
  s->add_option("--fov", c.fov, "Vertical field of view, degrees (orbit default 30; 0 = orthographic)")->check(fest::cli::range(0.0, 179.0));
  s->add_option("--eye", t.eye, "Eye position X,Y,Z (look-at and off-axis cameras)");
  s->add_option("--look-at", t.look_at, "Look-at point X,Y,Z");
  s->add_option("--up", t.up, "Up vector of the look-at camera");
  s->add_option("--screen", t.screen, "Off-axis camera: screen corners 'PA;PB;PC' (lower left; lower right; upper left)");
  s->add_option("--near", c.near, "Rays start this far from the eye (world units)");
  s->add_option("--mirror", t.mirror, "Beam-splitter mirror plane NX,NY,NZ,DELTA (n.x = delta) of the off-axis camera");
  s->add_option("--mirror-poly", t.mirror_poly, "The mirror's outline 'x,y,z;x,y,z;...' (convex); lines of sight outside show background");
  s->add_option("--stereo", c.stereo, "Render a stereo pair with this eye separation (world units)");
  fest::cli::enum_words<StereoLayout>(
      s->add_option("--stereo-layout", c.stereo_layout, "files (-o pattern with %s = L/R), sbs, tb or anaglyph"),
      {{"files", StereoLayout::files}, {"sbs", StereoLayout::sbs}, {"tb", StereoLayout::tb}, {"anaglyph", StereoLayout::anaglyph}});
  s->add_option("--head-right", t.head_right, "Direction from the left to the right eye (default: screen/camera right)");
}

Vec3 vec3(const std::string& text, const char* flag) {
  const auto v = number_list(text, 3, 3, flag);
  return {v[0], v[1], v[2]};
}

// "x,y,z;x,y,z;...": points separated by ';'.
std::vector<Vec3> points(const std::string& text, const char* flag) {
  std::vector<Vec3> out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(';', begin);
    out.push_back(vec3(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin), flag));
    if (end == std::string::npos) return out;
    begin = end + 1;
  }
}

void fill(CameraArgs& c, const CameraText& t) {
  const auto size = fest::cli::integer_list(t.size, 2, 2, "--size", 1, 16384, 'x');
  c.width = static_cast<int>(size[0]), c.height = static_cast<int>(size[1]);
  c.view = number_list(t.view, 2, 3, "--view");
  if (!t.eye.empty()) c.eye = vec3(t.eye, "--eye");
  if (!t.look_at.empty()) c.look_at = vec3(t.look_at, "--look-at");
  c.up = vec3(t.up, "--up");
  if (!t.screen.empty()) c.screen = points(t.screen, "--screen");
  if (!t.mirror.empty()) {
    const auto m = number_list(t.mirror, 4, 4, "--mirror");
    c.mirror = std::array<double, 4>{m[0], m[1], m[2], m[3]};
  }
  if (!t.mirror_poly.empty()) c.mirror_poly = points(t.mirror_poly, "--mirror-poly");
  if (!t.head_right.empty()) c.head_right = vec3(t.head_right, "--head-right");
}

void add_raw(CLI::App* s, std::string& raw, std::string& spacing) {
  s->add_option("--raw", raw, "Headerless input: NX,NY,NZ,TYPE[,little|big] (TYPE uint8, int8, uint16, int16, uint32, "
                              "int32, uint64, int64, float32, float64; x fastest; little-endian by default)");
  s->add_option("--raw-spacing", spacing, "Sample spacing SX,SY,SZ of --raw input (default 1,1,1)");
}

// --raw and --raw-spacing -> the layout (docs/volrender.md "Inputs").
std::optional<fest::formats::RawLayout> raw_layout(const std::string& raw, const std::string& spacing) {
  if (raw.empty()) {
    if (!spacing.empty()) throw fest::usage_error("--raw-spacing needs --raw");
    return std::nullopt;
  }
  fest::formats::RawLayout layout;
  try {
    layout = fest::formats::parse_raw_layout(raw);
  } catch (const std::invalid_argument& e) {
    throw fest::usage_error("--raw {}", e.what());
  }
  if (!spacing.empty()) {
    const auto sp = number_list(spacing, 3, 3, "--raw-spacing");
    for (int a = 0; a < 3; ++a) {
      if (!(sp[a] > 0)) throw fest::usage_error("--raw-spacing takes positive spacings, not '{}'", spacing);
      layout.spacing[a] = sp[a];
    }
  }
  return layout;
}

// --iso V[:alpha][,V:alpha...] and --iso-color r,g,b[;r,g,b...]
std::vector<fest::raycast::IsoLayer> iso_layers(const std::string& isos, const std::string& colors) {
  std::vector<fest::raycast::IsoLayer> out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = isos.find(',', begin);
    const std::string item = isos.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    const auto v = number_list(item, 1, 2, "--iso", ':');
    fest::raycast::IsoLayer L;
    L.value = v[0];
    if (v.size() > 1) {
      L.alpha = v[1];
      if (!(L.alpha >= 0 && L.alpha <= 1)) throw fest::usage_error("--iso opacity must be in [0,1] ('{}')", item);
    }
    out.push_back(L);
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  if (!colors.empty()) {
    const auto c = points(colors, "--iso-color");
    if (c.size() > out.size()) throw fest::usage_error("--iso-color names more colours than iso-values");
    for (std::size_t k = 0; k < c.size(); ++k) out[k].color = c[k];
  }
  return out;
}

// --screen-mask: a PNG file, or a polygon 'x,y;x,y;...' in pixel coordinates -- a text
// with a comma that names no existing file and does not end in .png (docs/volrender.md).
void screen_mask(RenderArgs& r, const std::string& text) {
  if (text.empty()) return;
  const bool png = text.size() >= 4 && (text.compare(text.size() - 4, 4, ".png") == 0 || text.compare(text.size() - 4, 4, ".PNG") == 0);
  std::error_code ec;
  if (png || text.find(',') == std::string::npos || std::filesystem::exists(text, ec)) {
    r.screen_mask = text;
    return;
  }
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(';', begin);
    const auto v = number_list(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin), 2, 2,
                               "--screen-mask polygon vertex");
    r.screen_polygon.push_back({v[0], v[1]});
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  if (r.screen_polygon.size() < 3)
    throw fest::usage_error("--screen-mask polygon needs at least 3 vertices x,y;x,y;x,y, got {} ('{}')", r.screen_polygon.size(), text);
  double twice_area = 0;
  for (std::size_t k = 0; k < r.screen_polygon.size(); ++k) {
    const auto& a = r.screen_polygon[k];
    const auto& b = r.screen_polygon[(k + 1) % r.screen_polygon.size()];
    twice_area += a.x * b.y - b.x * a.y;
  }
  if (twice_area == 0) throw fest::usage_error("--screen-mask polygon has zero area ('{}')", text);
}

void fill(RenderArgs& r, const RenderText& t) {
  if (t.frame == "all") {
    r.all_frames = true;
  } else if (!t.frame.empty()) {
    r.frame = static_cast<long>(fest::cli::integer_list(t.frame, 1, 1, "--frame", 0, std::numeric_limits<long>::max() / 2)[0]);
  }
  r.raw = raw_layout(t.raw, t.raw_spacing);
  if (t.bg == "none") {
    r.keep_alpha = true;
  } else {
    const auto bg = number_list(t.bg, 3, 4, "--bg");
    r.background = {bg[0], bg[1], bg[2]};
  }
  const auto ph = number_list(t.phong, 4, 4, "--phong");
  r.phong = {ph[0], ph[1], ph[2], ph[3]};
  if (!t.window.empty()) {
    const auto w = number_list(t.window, 2, 2, "--window");
    r.window = std::array<double, 2>{w[0], w[1]};
  }
  if (!t.iso.empty()) r.isos = iso_layers(t.iso, t.iso_color);
  if (t.slice_axis == "x" || t.slice_axis == "y" || t.slice_axis == "z") r.slice_axis.index_axis = t.slice_axis[0] - 'x';
  else r.slice_axis.normal = vec3(t.slice_axis, "--slice-axis");
  if (!t.slice_at.empty()) r.slice_at = number_list(t.slice_at, 1, 4096, "--slice-at");
  if (!t.contours.empty()) {
    const auto c = number_list(t.contours, 3, 3, "--contours", ':');
    r.contours = Contours{c[0], c[1], c[2]};
  }
  const auto mc = number_list(t.mesh_color, 3, 3, "--mesh-color");
  r.mesh_color = {mc[0], mc[1], mc[2]};
  screen_mask(r, t.screen_mask);
}

// --component mag|x|y|z
void component(CLI::App* s, fest::formats::VectorComponent& c) {
  using fest::formats::VectorComponent;
  fest::cli::enum_words<VectorComponent>(s->add_option("--component", c, "Vector fields: mag, x, y or z"),
                                         {{"mag", VectorComponent::mag}, {"x", VectorComponent::x}, {"y", VectorComponent::y}, {"z", VectorComponent::z}});
}

}  // namespace

int main(int argc, char** argv) {
  using fest::raycast::Mode;
  CLI::App app{"Headless CPU volume renderer: DVR (transfer functions, pre-integration, shading), MIP, MinIP,\n"
               "average and iso ray casting; orbit, look-at, off-axis, stereo and beam-splitter-mirror cameras.",
               "volrender"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error (also a bad camera), 3 bad input, 4 I/O error.\n"
             "See volrender(1).");

  RenderArgs ra;
  RenderText rt;
  CameraText ct;
  std::vector<std::pair<CLI::App*, Mode>> modes;
  const std::pair<const char*, Mode> names[] = {{"dvr", Mode::dvr}, {"mip", Mode::mip}, {"minip", Mode::minip},
                                                {"avg", Mode::avg}, {"iso", Mode::iso}, {"slices", Mode::slices}};
  for (const auto& [m, mode] : names) {
    const std::string help = mode == Mode::dvr     ? "Direct volume rendering (emission-absorption)"
                             : mode == Mode::mip   ? "Maximum intensity projection"
                             : mode == Mode::minip ? "Minimum intensity projection"
                             : mode == Mode::avg   ? "Average along the ray"
                             : mode == Mode::iso   ? "Shaded (semi-transparent) isosurfaces"
                                                   : "Stacked slice planes with iso-contour bands (the chapter's fig. 4.5b)";
    auto* s = app.add_subcommand(m, help);
    modes.emplace_back(s, mode);
    s->add_option("input", ra.input, "Volume: NIfTI, NRRD, MHA, VTI or a fest frame stream (- = stdin)");
    s->add_option("-o,--output", ra.output, "Image (- = stdout; %s pattern for stereo files; %d pattern for --frame all)");
    s->add_option("--to", ra.to, "png (8-bit sRGB), pfm or exr (linear float)");
    s->add_option("--field", ra.field, "VTI point array or frame-stream field");
    component(s, ra.component);
    s->add_option("--frame", rt.frame, "Frame of a frame stream or 4-D series (0-based; default the last), or all: one image per frame");
    add_raw(s, rt.raw, rt.raw_spacing);
    s->add_option("--spp", ra.spp, "Rays per pixel: 1, 4, 9 or 16 (stratified, box-filtered)")->check(CLI::IsMember({1, 4, 9, 16}));
    s->add_option("--bg", rt.bg, "Background r,g,b (linear) or none (keep alpha)");
    s->add_flag("--linear", ra.linear, "PNG holds linear values instead of sRGB");
    s->add_option("--depth-image", ra.depth_image, "Write per-pixel ray distance (PFM)");
    s->add_option("--step", ra.step, "Sample spacing in voxel units (smallest spacing)");
    s->add_flag("--jitter", ra.jitter, "Per-pixel deterministic jitter of the sample positions");
    fest::cli::enum_words<bool>(s->add_option("--interp", ra.nearest, "trilinear or nearest"), {{"trilinear", false}, {"nearest", true}});
    s->add_option("--tf", ra.tf, "Transfer function: CSV value,r,g,b,a / ParaView JSON file, or a preset "
                                 "(grey, ct-bone, ct-skin-bone, mri, flow, rainbow, contour-only)");
    fest::cli::enum_words<fest::raycast::OpacityMode>(
        s->add_option("--tf-mode", ra.tf_mode, "opacity (a per --tf-unit) or extinction (tau per --tf-unit)"),
        {{"opacity", fest::raycast::OpacityMode::opacity}, {"extinction", fest::raycast::OpacityMode::extinction}});
    s->add_option("--tf-unit", ra.tf_unit, "Reference length of the TF opacity, voxel units");
    s->add_flag("--preint", ra.preint, "Pre-integrated classification");
    fest::cli::enum_words<bool>(s->add_option("--shade", ra.shade, "Blinn-Phong gradient shading on or off"), {{"on", true}, {"off", false}});
    s->add_option("--phong", rt.phong, "ka,kd,ks,exponent");
    s->add_flag("--two-sided", ra.two_sided, "Light both sides of the gradient");
    s->add_option("--ert", ra.ert, "Early ray termination at this accumulated opacity");
    s->add_option("--window", rt.window, "mip/minip/avg: grey window lo,hi instead of the TF colour");
    s->add_option("--iso", rt.iso, "iso: V[:alpha][,V:alpha...]");
    s->add_option("--iso-color", rt.iso_color, "iso: r,g,b[;r,g,b...] per iso-value");
    fest::cli::enum_words<Gradients>(
        s->add_option("--gradients", ra.gradients,
                      "Shading gradients: otf (on the fly), cache (value and gradient, 16 bytes/voxel) or auto (cache up to 64 M voxels)"),
        {{"otf", Gradients::otf}, {"cache", Gradients::cache}, {"auto", Gradients::automatic}});
    s->add_flag("--no-skip", ra.no_skip, "Disable empty-space skipping (same image; for comparisons)");
    s->add_option("--slice-axis", rt.slice_axis, "slices: plane normal x, y, z (index axes) or nx,ny,nz (world)");
    s->add_option("--slices", ra.slice_count, "slices: number of planes, equally spaced over the volume")->check(fest::cli::range(1, 4096));
    s->add_option("--slice-at", rt.slice_at, "slices: plane offsets along the normal (world units), instead of --slices");
    s->add_option("--contours", rt.contours, "slices: contour levels c0:dc:n");
    s->add_option("--contour-width", ra.contour_width, "slices: contour band width, data units");
    s->add_option("--contour-width-world", ra.contour_width_world, "slices: contour band width in world units (W |grad f| in data units)");
    s->add_flag("--slice-frame", ra.slice_frame, "slices: draw each plane's outline on the volume box (white, one voxel wide)");
    s->add_option("--contour-alpha", ra.contour_alpha, "slices: contour opacity")->check(fest::cli::range(0.0, 1.0));
    s->add_option("--mesh", ra.mesh, "Opaque triangle mesh (PLY, OBJ, OFF, STL, Draco; world units) composited with depth");
    s->add_option("--mesh-color", rt.mesh_color, "Mesh colour r,g,b (linear)");
    s->add_option("--screen-mask", rt.screen_mask,
                  "M.png of the image's size (cast the pixels neither black nor transparent) or a polygon 'x,y;x,y;...' in pixel "
                  "coordinates, y down (cast the pixels whose centres are inside, even-odd); the others stay background");
    s->add_option("--camera-json", ra.camera_json, "Write the camera(s) as JSON");
    s->add_option("--report", ra.report, "Write rays, samples, skipped samples and timings as JSON");
    add_camera(s, ra.camera, ct);
    fest::cli::add_threads(*s, ra.threads);
    fest::cli::add_progress(*s, ra.progress);
  }
  CameraPrintArgs cp;
  CameraText cpt;
  std::string cp_raw, cp_raw_spacing;
  auto* c = app.add_subcommand("camera", "Print the camera(s) -- rays' frame, off-axis frustum and view matrix -- as JSON");
  bool print = false;
  c->add_flag("--print", print, "Print (the default action)");
  c->add_option("input", cp.input, "Volume (orbit cameras need its bounds)");
  add_raw(c, cp_raw, cp_raw_spacing);
  add_camera(c, cp.camera, cpt);

  CompositeArgs ca;
  auto* k = app.add_subcommand("composite", "Stack images with the over operator (the first on top) in linear light: a showcase screen from its viewers' parts");
  k->add_option("images", ca.inputs, "Images (PNG, PAM, EXR, ...), top first")->required();
  k->add_option("-o,--output", ca.output, "PNG output (- = stdout)");

  return fest::cli::run(app, argc, argv, [&]() -> int {
    for (const auto& [s, mode] : modes)
      if (*s) {
        ra.mode = mode;
        fill(ra, rt);
        fill(ra.camera, ct);
        return run_render(ra);
      }
    if (*c) {
      cp.raw = raw_layout(cp_raw, cp_raw_spacing);
      fill(cp.camera, cpt);
      return run_camera_print(cp);
    }
    if (*k) return run_composite(ca);
    return 2;
  });
}
