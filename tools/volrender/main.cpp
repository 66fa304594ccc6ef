// volrender: headless CPU volume ray casting (DVR, MIP, MinIP, average, iso) with orbit,
// look-at, off-axis, stereo and beam-splitter-mirror cameras (docs/volrender.md). Flags
// only; the work is in cmd_render.cpp.

#include "cli/cli.hpp"
#include "commands.hpp"

namespace {

void add_camera(CLI::App* s, fest::volrender::CameraArgs& c) {
  s->add_option("--size", c.size, "Image size WxH")->default_val("512x512");
  s->add_option("--view", c.view, "Orbit camera: AZ,EL[,ROLL] degrees around the volume centre (0,0 looks along +y, z up)");
  s->add_option("--zoom", c.zoom, "Orbit camera magnification");
  s->add_option("--fov", c.fov, "Vertical field of view, degrees (orbit default 30; 0 = orthographic)")->check(CLI::Range(0.0, 179.0));
  s->add_option("--eye", c.eye, "Eye position X,Y,Z (look-at and off-axis cameras)");
  s->add_option("--look-at", c.look_at, "Look-at point X,Y,Z");
  s->add_option("--up", c.up, "Up vector of the look-at camera");
  s->add_option("--screen", c.screen, "Off-axis camera: screen corners 'PA;PB;PC' (lower left; lower right; upper left)");
  s->add_option("--near", c.near, "Rays start this far from the eye (world units)");
  s->add_option("--mirror", c.mirror, "Beam-splitter mirror plane NX,NY,NZ,DELTA (n.x = delta) of the off-axis camera");
  s->add_option("--mirror-poly", c.mirror_poly, "The mirror's outline 'x,y,z;x,y,z;...' (convex); lines of sight outside show background");
  s->add_option("--stereo", c.stereo, "Render a stereo pair with this eye separation (world units)");
  s->add_option("--stereo-layout", c.stereo_layout, "files (-o pattern with %s = L/R), sbs, tb or anaglyph");
  s->add_option("--head-right", c.head_right, "Direction from the left to the right eye (default: screen/camera right)");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fest::volrender;
  CLI::App app{"Headless CPU volume renderer: DVR (transfer functions, pre-integration, shading), MIP, MinIP,\n"
               "average and iso ray casting; orbit, look-at, off-axis, stereo and beam-splitter-mirror cameras.",
               "volrender"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error (also a bad camera), 3 bad input, 4 I/O error.\n"
             "See volrender(1).");

  RenderArgs ra;
  std::vector<CLI::App*> modes;
  for (const char* m : {"dvr", "mip", "minip", "avg", "iso", "slices"}) {
    const std::string help = std::string(m) == "dvr"     ? "Direct volume rendering (emission-absorption)"
                             : std::string(m) == "mip"   ? "Maximum intensity projection"
                             : std::string(m) == "minip" ? "Minimum intensity projection"
                             : std::string(m) == "avg"   ? "Average along the ray"
                             : std::string(m) == "iso"   ? "Shaded (semi-transparent) isosurfaces"
                                                         : "Stacked slice planes with iso-contour bands (the chapter's fig. 4.5b)";
    auto* s = app.add_subcommand(m, help);
    modes.push_back(s);
    s->add_option("input", ra.input, "Volume: NIfTI, NRRD, MHA, VTI or a fest frame stream (- = stdin)");
    s->add_option("-o,--output", ra.output, "Image (- = stdout; %s pattern for stereo files)");
    s->add_option("--to", ra.to, "png (8-bit sRGB), pfm or exr (linear float)");
    s->add_option("--field", ra.field, "VTI point array or frame-stream field");
    s->add_option("--component", ra.component, "Vector fields: mag, x, y or z")->check(CLI::IsMember({"mag", "x", "y", "z"}));
    s->add_option("--frame", ra.frame, "Frame of a frame stream (0-based; default the last)")->check(CLI::NonNegativeNumber);
    s->add_option("--spp", ra.spp, "Rays per pixel: 1, 4, 9 or 16 (stratified, box-filtered)")->check(CLI::IsMember({1, 4, 9, 16}));
    s->add_option("--bg", ra.bg, "Background r,g,b (linear) or none (keep alpha)");
    s->add_flag("--linear", ra.linear, "PNG holds linear values instead of sRGB");
    s->add_option("--depth-image", ra.depth_image, "Write per-pixel ray distance (PFM)");
    s->add_option("--step", ra.step, "Sample spacing in voxel units (smallest spacing)");
    s->add_flag("--jitter", ra.jitter, "Per-pixel deterministic jitter of the sample positions");
    s->add_option("--interp", ra.interp, "trilinear or nearest")->check(CLI::IsMember({"trilinear", "nearest"}));
    s->add_option("--tf", ra.tf, "Transfer function: CSV value,r,g,b,a / ParaView JSON file, or a preset "
                                 "(grey, ct-bone, ct-skin-bone, mri, flow, rainbow, contour-only)");
    s->add_option("--tf-mode", ra.tf_mode, "opacity (a per --tf-unit) or extinction (tau per --tf-unit)")
        ->check(CLI::IsMember({"opacity", "extinction"}));
    s->add_option("--tf-unit", ra.tf_unit, "Reference length of the TF opacity, voxel units");
    s->add_flag("--preint", ra.preint, "Pre-integrated classification");
    s->add_option("--shade", ra.shade, "Blinn-Phong gradient shading on or off")->check(CLI::IsMember({"on", "off"}));
    s->add_option("--phong", ra.phong, "ka,kd,ks,exponent");
    s->add_flag("--two-sided", ra.two_sided, "Light both sides of the gradient");
    s->add_option("--ert", ra.ert, "Early ray termination at this accumulated opacity");
    s->add_option("--window", ra.window, "mip/minip/avg: grey window lo,hi instead of the TF colour");
    s->add_option("--iso", ra.iso, "iso: V[:alpha][,V:alpha...]");
    s->add_option("--iso-color", ra.iso_color, "iso: r,g,b[;r,g,b...] per iso-value");
    s->add_option("--gradients", ra.gradients, "Shading gradients: otf (on the fly), cache (value and gradient, 16 bytes/voxel) or auto (cache up to 64 M voxels)")
        ->check(CLI::IsMember({"otf", "cache", "auto"}));
    s->add_flag("--no-skip", ra.no_skip, "Disable empty-space skipping (same image; for comparisons)");
    s->add_option("--slice-axis", ra.slice_axis, "slices: plane normal x, y, z (index axes) or nx,ny,nz (world)");
    s->add_option("--slices", ra.slice_count, "slices: number of planes, equally spaced over the volume")->check(CLI::Range(1, 4096));
    s->add_option("--slice-at", ra.slice_at, "slices: plane offsets along the normal (world units), instead of --slices");
    s->add_option("--contours", ra.contours, "slices: contour levels c0:dc:n");
    s->add_option("--contour-width", ra.contour_width, "slices: contour band width, data units");
    s->add_option("--contour-width-world", ra.contour_width_world, "slices: contour band width in world units (W |grad f| in data units)");
    s->add_flag("--slice-frame", ra.slice_frame, "slices: draw each plane's outline on the volume box (white, one voxel wide)");
    s->add_option("--contour-alpha", ra.contour_alpha, "slices: contour opacity")->check(CLI::Range(0.0, 1.0));
    s->add_option("--mesh", ra.mesh, "Opaque triangle mesh (PLY, OBJ, OFF, STL, Draco; world units) composited with depth");
    s->add_option("--mesh-color", ra.mesh_color, "Mesh colour r,g,b (linear)");
    s->add_option("--camera-json", ra.camera_json, "Write the camera(s) as JSON");
    s->add_option("--report", ra.report, "Write rays, samples, skipped samples and timings as JSON");
    add_camera(s, ra.camera);
    fest::cli::add_threads(*s, ra.threads);
  }
  CameraPrintArgs cp;
  auto* c = app.add_subcommand("camera", "Print the camera(s) -- rays' frame, off-axis frustum and view matrix -- as JSON");
  bool print = false;
  c->add_flag("--print", print, "Print (the default action)");
  c->add_option("input", cp.input, "Volume (orbit cameras need its bounds)");
  add_camera(c, cp.camera);

  CompositeArgs ca;
  auto* k = app.add_subcommand("composite", "Stack images with the over operator (the first on top) in linear light: a showcase screen from its viewers' parts");
  k->add_option("images", ca.inputs, "Images (PNG, PAM, EXR, ...), top first")->required();
  k->add_option("-o,--output", ca.output, "PNG output (- = stdout)");

  return fest::cli::run(app, argc, argv, [&]() -> int {
    for (auto* s : modes)
      if (*s) {
        ra.mode = s->get_name();
        return run_render(ra);
      }
    if (*c) return run_camera_print(cp);
    if (*k) return run_composite(ca);
    return 2;
  });
}
