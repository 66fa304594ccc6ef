// resample: prefilter -> sample -> reconstruct, and the numbers that say how well
// (docs/resample.md; Schilling, "Some Notes on Sampling in Computer Graphics").
//
// Wiring only: this file declares the subcommands and their flags; cmd_*.cpp connect
// formats/image to lib/sampling.

#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/number_list.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "sampling/kernel_params.hpp"
#include "sizes.hpp"

namespace {

using namespace fest::resample_tool;
using fest::sampling::ClampMode;
using fest::sampling::EdgeMode;

// --to NAME: the output format, read as the flag is parsed (an unknown name is a usage error).
CLI::Option* add_format(CLI::App* sub, std::optional<fest::formats::OutputFormat>& to, const std::string& help) {
  return sub->add_option_function<std::string>(
      "--to,--format", [&to](const std::string& name) { to = fest::formats::output_format_from_name(name); }, help);
}

void add_output(CLI::App* sub, ImageOutput& o) {
  sub->add_option("-o,--output", o.output, "Output file, or - for standard output")->default_val("-");
  add_format(sub, o.to, "Output format: png jpg pgm ppm pam pfm exr tiff (default: -o extension, else PNG/PFM)");
  fest::cli::enum_words<OutputDepth>(sub->add_option("--depth", o.depth, "Output depth: 8, 16, f16 (EXR half), f32"),
                        {{"8", OutputDepth::u8}, {"16", OutputDepth::u16}, {"f16", OutputDepth::f16}, {"f32", OutputDepth::f32}});
  sub->add_option("--quality", o.quality, "JPEG output quality, 1 (smallest) to 100 (best)")
      ->check(fest::cli::range(1, 100))
      ->default_val(95);
  sub->add_flag("--flatten", o.flatten, "PGM/PPM/JPEG output: composite alpha over --background (default white)");
  sub->add_option_function<std::string>(
      "--background",
      [&o](const std::string& text) {
        const auto rgb = fest::cli::integer_list(text, 3, 3, "--background", 0, 255);
        for (int c = 0; c < 3; ++c) o.background[std::size_t(c)] = double(rgb[std::size_t(c)]) / 255.0;
        o.flatten = true;
      },
      "Background R,G,B (sRGB codes 0-255) that --flatten composites over; implies --flatten");
  fest::cli::add_progress(*sub, o.progress);
}

const std::vector<std::pair<std::string, MipFilter>> kMipFilters{
    {"box", MipFilter::box}, {"gaussian", MipFilter::gaussian}, {"lanczos3", MipFilter::lanczos3}};

// --param k=v (repeatable; each may also hold k=v,k2=v2) -> the scene's parameters.
std::map<std::string, double> scene_params(const std::vector<std::string>& given) {
  std::map<std::string, double> out;
  for (const auto& g : given) {
    std::size_t start = 0;
    while (start <= g.size()) {
      const std::size_t comma = g.find(',', start);
      const std::string item = g.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      const auto eq = item.find('=');
      if (eq == std::string::npos || eq == 0) throw fest::usage_error("--param: '{}' is not key=value", item);
      char* end = nullptr;
      const std::string value = item.substr(eq + 1);
      const double v = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !std::isfinite(v)) throw fest::usage_error("--param: '{}' is not a number", item);
      out[item.substr(0, eq)] = v;
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

// --zoneplate numax=1[,width=W,height=H] (empty: every default).
ZonePlate zone_plate(const std::string& text) {
  const auto zp = fest::sampling::parse_kernel_params("zoneplate", text, {{"numax", 1}, {"width", 0}, {"height", 0}});
  ZonePlate z;
  z.numax = zp.at("numax");
  z.width = static_cast<int>(zp.at("width"));
  z.height = static_cast<int>(zp.at("height"));
  return z;
}

// --pixel-filter NAME[:params][,radius=R] -> the kernel and the stretch that gives it radius R.
std::pair<fest::sampling::Kernel, double> stretched_kernel(const std::string& spec) {
  std::string rest = spec;
  double radius = 0;
  const auto pos = rest.find("radius=");
  if (pos != std::string::npos && pos > 0 && (rest[pos - 1] == ':' || rest[pos - 1] == ',')) {
    const auto end = rest.find(',', pos);
    const std::string value = rest.substr(pos + 7, end == std::string::npos ? std::string::npos : end - pos - 7);
    char* stop = nullptr;
    radius = std::strtod(value.c_str(), &stop);
    if (value.empty() || *stop != '\0' || !(radius > 0 && radius <= 64))
      throw fest::usage_error("--pixel-filter: radius '{}' must be a number in (0, 64]", value);
    rest.erase(pos - 1, (end == std::string::npos ? rest.size() : end) - pos + 1);
  }
  const fest::sampling::Kernel k = fest::sampling::make_kernel(rest);
  if (!k.reconstruction.empty()) throw fest::usage_error("--pixel-filter cannot be a dual prefilter");
  const double scale = radius > 0 && k.radius > 0 && std::isfinite(k.radius) ? radius / k.radius : 1.0;
  return {k, scale};
}

// --pixel-filter for rd.scene (after rd.params): the point scene takes the radial
// lowpass/bandpass filters the others do not.
void set_pixel_filter(RenderArgs& rd, const std::string& spec) {
  const bool radial = spec.rfind("lowpass", 0) == 0 || spec.rfind("bandpass", 0) == 0;
  if (radial && rd.scene != "point") throw fest::usage_error("--pixel-filter {} is for --scene point only", spec);
  if (rd.scene != "point") {
    std::tie(rd.pixel_filter, rd.filter_scale) = stretched_kernel(spec);
    return;
  }
  const fest::sampling::KernelSpelling s = fest::sampling::split_kernel_spelling(spec);
  if (s.name == "bandpass") {
    for (const auto& [k, v] : fest::sampling::parse_kernel_params("bandpass", s.rest, {{"lo", 0.2}})) rd.params[k] = v;
    rd.point_filter = "bandpass";
  } else if (s.name == "lowpass") {
    if (!s.rest.empty()) throw fest::usage_error("--pixel-filter lowpass takes no parameters");
  } else {
    rd.point_filter = spec;
  }
}

// --map plane:h=..,pitch=..,fov=..,period=..
PlaneView plane_view(const std::string& text) {
  const fest::sampling::KernelSpelling s = fest::sampling::split_kernel_spelling(text);
  if (s.name != "plane") throw fest::usage_error("--map: unknown mapping '{}' (plane:h=..,pitch=..,fov=..,period=..)", s.name);
  const auto p = fest::sampling::parse_kernel_params("plane", s.rest, {{"h", 1}, {"pitch", 10}, {"fov", 60}, {"period", 1}});
  return PlaneView{p.at("h"), p.at("pitch"), p.at("fov"), p.at("period")};
}

// ---- one registration function per subcommand: flags -> its typed options (and the
// spellings read after parsing, in the order the checks name the first bad flag).

struct ResizeFlags {
  ResizeArgs a;
  std::string filter = "mitchell", size;
};

CLI::App* add_resize(CLI::App& app, ResizeFlags& f) {
  ResizeArgs& rz = f.a;
  auto* resize = app.add_subcommand("resize", "Resize an image (separable, linear light, premultiplied alpha)");
  resize->add_option("input", rz.input, "Input image, or - for standard input")->default_val("-");
  add_output(resize, rz.out);
  resize->add_option("--size", f.size, "Target size WxH");
  resize->add_option("--width", rz.width, "Target width (height keeps the aspect ratio)")
      ->check(fest::cli::positive);
  resize->add_option("--height", rz.height, "Target height (width keeps the aspect ratio)")
      ->check(fest::cli::positive);
  resize->add_option("--scale", rz.scale, "Scale factor S or Sx,Sy")->delimiter(',')->allow_extra_args(false)
      ->check(fest::cli::positive);
  resize->add_option("--filter", f.filter, "Kernel NAME[:k=v,...] (see `resample kernel`)")->default_val("mitchell");
  resize->add_option("--shift", rz.shift, "Sub-pixel shift dx,dy in input pixels")->delimiter(',')->allow_extra_args(false);
  fest::cli::enum_words<EdgeMode>(resize->add_option("--edge", rz.edge, "Edges: clamp, reflect, wrap, zero"),
                        {{"clamp", EdgeMode::clamp}, {"reflect", EdgeMode::reflect}, {"wrap", EdgeMode::wrap}, {"zero", EdgeMode::zero}})->default_str("clamp");
  fest::cli::enum_words<ResizeColor>(resize->add_option("--colorspace", rz.colorspace, "auto, srgb, linear, codes (filter the stored numbers)"),
                        {{"auto", ResizeColor::automatic}, {"srgb", ResizeColor::srgb}, {"linear", ResizeColor::linear},
                         {"codes", ResizeColor::codes}})->default_str("auto");
  fest::cli::enum_words<AlphaMode>(resize->add_option("--alpha", rz.alpha, "premul, straight, none"),
                        {{"premul", AlphaMode::premul}, {"straight", AlphaMode::straight}, {"none", AlphaMode::none}})->default_str("premul");
  fest::cli::enum_words<ClampMode>(resize->add_option("--clamp", rz.clamp, "Anti-ringing: none, range, local (default: range for integer output)"),
                        {{"auto", ClampMode::automatic}, {"none", ClampMode::none}, {"range", ClampMode::range},
                         {"local", ClampMode::local}})->default_str("auto");
  resize->add_flag("--hicomp", rz.hicomp, "Highlight compression for HDR input (x > 1 filtered as 1 + ln x)");
  resize->add_flag("--dither", rz.dither, "Triangular ±½ LSB dither before rounding");
  resize->add_option("--seed", rz.seed, "Dither seed")->default_val(1);
  fest::cli::add_threads(*resize, rz.threads);
  return resize;
}

int resize(ResizeFlags& f) {
  // In this order, all before the input is read: the first bad flag is the one named.
  f.a.filter = fest::sampling::make_kernel(f.filter);
  if (!f.size.empty()) f.a.size = parse_size(f.size, "--size");  // a bad --size is a usage error even before input
  return run_resize(f.a);
}

struct DisplayFlags {
  DisplayArgs a;
  std::string model = "lcd";
};

CLI::App* add_display(CLI::App& app, DisplayFlags& f) {
  auto* display = app.add_subcommand("display", "Magnify by an integer factor with a display's point response");
  display->add_option("input", f.a.input, "Input image, or - for standard input")->default_val("-");
  add_output(display, f.a.out);
  display->add_option("--model", f.model, "lcd, tent, bspline, gaussian:sigma=S, crt[:sx=0.45,sy=0.35]")->default_val("lcd");
  display->add_option("--factor", f.a.factor, "Magnification (integer)")->default_val(8)->check(fest::cli::range(1, 64));
  fest::cli::add_threads(*display, f.a.threads);
  return display;
}

int display(DisplayFlags& f) {
  if (f.a.factor < 1 || f.a.factor > 64) throw fest::usage_error("--factor {} is out of range [1, 64]", f.a.factor);
  f.a.model = fest::sampling::make_display_model(f.model);
  return run_display(f.a);
}

struct MipFlags {
  MipArgs a;
  std::string action;
};

CLI::App* add_mip(CLI::App& app, MipFlags& f) {
  MipArgs& mp = f.a;
  auto* mip = app.add_subcommand("mip", "Build a mip-map pyramid: PREFIX_<k>.png (or .exr for float), k = 0 full size");
  mip->add_option("action", f.action, "build")->required();
  mip->add_option("input", mp.input, "Input image, or - for standard input")->default_val("-");
  mip->add_option("-o,--output", mp.prefix, "Prefix of the level files")->required();
  fest::cli::enum_words(mip->add_option("--filter", mp.filter, "box, gaussian, lanczos3"), kMipFilters)->default_str("box");
  mip->add_option("--levels", mp.levels, "Number of levels (0: down to 1x1)")->default_val(0)->check(fest::cli::range(0, 40));
  add_format(mip, mp.to, "Level file format");
  fest::cli::add_threads(*mip, mp.threads);
  return mip;
}

int mip(MipFlags& f) {
  if (f.action != "build") throw fest::usage_error("mip: unknown action '{}' (build)", f.action);
  if (f.a.prefix.empty()) throw fest::usage_error("mip build needs -o PREFIX");
  return run_mip(f.a);
}

struct RenderFlags {
  RenderArgs a;
  std::vector<std::string> params;
  std::string size = "256x256", pattern = "jitter", pixel_filter = "box";
};

CLI::App* add_render(CLI::App& app, RenderFlags& f) {
  RenderArgs& rd = f.a;
  auto* render = app.add_subcommand("render", "Render an analytic scene with supersampling");
  add_output(render, rd.out);
  render->add_option("--scene", rd.scene, "zoneplate, sine, siemens, edges, point, checker-plane")->default_val("zoneplate");
  render->add_option("--param", f.params, "Scene parameter key=value (repeatable)")->allow_extra_args(false);
  render->add_option("--size", f.size, "Image size WxH")->default_val("256x256");
  render->add_option("--spp", rd.spp, "Samples per pixel")->default_val(16)->check(fest::cli::range(1, 65536));
  render->add_option("--pattern", f.pattern, "regular, jitter, random, rooks, rgss, poisson, halton, sobol")->default_val("jitter");
  render->add_option("--pixel-filter", f.pixel_filter, "Pixel filter NAME[:radius=R]; lowpass|bandpass[:lo=..] for --scene point")->default_val("box");
  render->add_option("--seed", rd.seed, "Seed of the sample patterns")->default_val(1);
  render->add_flag("--ground-truth", rd.ground_truth, "Dense jittered ground truth (--gt-spp samples)");
  fest::cli::enum_words<RenderColor>(render->add_option("--colorspace", rd.colorspace, "Integer output: srgb (encoded codes) or linear (plain values)"),
                        {{"srgb", RenderColor::srgb}, {"linear", RenderColor::linear}})->default_str("srgb");
  render->add_option("--gt-spp", rd.gt_spp, "Samples per pixel of the ground truth")->default_val(4096)->check(fest::cli::range(1, 65536));
  fest::cli::add_threads(*render, rd.threads);
  return render;
}

int render(RenderFlags& f) {
  RenderArgs& rd = f.a;
  std::tie(rd.width, rd.height) = parse_size(f.size, "--size");
  rd.params = scene_params(f.params);
  if (!rd.ground_truth) rd.pattern = fest::sampling::parse_pattern(f.pattern);  // unused with --ground-truth
  set_pixel_filter(rd, f.pixel_filter);
  return run_render(rd);
}

struct TextureFlags {
  TextureArgs a;
  std::string size = "512x384", method = "trilinear", map;
};

CLI::App* add_texture(CLI::App& app, TextureFlags& f) {
  TextureArgs& tx = f.a;
  auto* texture = app.add_subcommand("texture", "Texture minification through mip-map lookups, EWA or dense ground truth");
  add_output(texture, tx.out);
  texture->add_option("--tex", tx.tex, "Texture image (filtered in linear light, one channel)")->required();
  texture->add_option("--map", f.map, "plane:h=1,pitch=10,fov=60,period=1 (ground plane seen by a pinhole camera)");
  texture->add_option("--uv", tx.uv, "Per-pixel texture coordinates in [0,1]: a 2-channel image of --size");
  texture->add_option("--size", f.size, "Screen size WxH")->default_val("512x384");
  texture->add_option("--method", f.method, "nearest, bilinear, trilinear, aniso:N[:gauss], ewa[:maxaniso=16]")->default_val("trilinear");
  fest::cli::enum_words(texture->add_option("--mip", tx.mip, "Pyramid filter: box, gaussian, lanczos3"), kMipFilters)->default_str("box");
  texture->add_option("--lod-bias", tx.lod_bias, "Added to the mip level")->default_val(0);
  texture->add_flag("--ground-truth", tx.ground_truth, "Dense supersampled reference instead of a lookup");
  texture->add_option("--aniso-mask", tx.aniso_mask, "Write the mask (0/255) of pixels whose footprint anisotropy exceeds this");
  texture->add_option("--seed", tx.seed, "Seed of the ground truth's samples")->default_val(1);
  fest::cli::add_threads(*texture, tx.threads);
  return texture;
}

int texture(TextureFlags& f) {
  TextureArgs& tx = f.a;
  if (tx.tex.empty()) throw fest::usage_error("texture needs --tex");
  if (f.map.empty() == tx.uv.empty()) throw fest::usage_error("texture needs exactly one of --map and --uv");
  std::tie(tx.width, tx.height) = parse_size(f.size, "--size");
  tx.method = fest::with_rewording({{"texture method: ", "--method "}},
                                   [&] { return fest::sampling::parse_texture_method(f.method); });
  if (!f.map.empty()) tx.map = plane_view(f.map);
  return run_texture(tx);
}

CLI::App* add_normalmip(CLI::App& app, NormalMipArgs& nm) {
  auto* normalmip = app.add_subcommand("normalmip", "Slope-moment pyramid of a normal or height map: PREFIX_<k>_normal.exr, PREFIX_<k>_cov.exr");
  normalmip->add_option("input", nm.input, "Normal or height map, or - for standard input")->default_val("-");
  normalmip->add_option("-o,--output", nm.prefix, "Prefix of the level files")->required();
  normalmip->add_flag("--normal-map", nm.normal_map, "The input is a normal map (integer codes: n = 2c - 1)");
  normalmip->add_flag("--height-map", nm.height_map, "The input is a height map (channel 0)");
  normalmip->add_option("--height-scale", nm.height_scale, "Height units per texel")->default_val(1);
  normalmip->add_flag("--naive", nm.naive, "Average normals instead (loses the slope covariance)");
  fest::cli::add_threads(*normalmip, nm.threads);
  return normalmip;
}

struct KernelFlags {
  KernelArgs a;
  std::string filter;  // required
};

CLI::App* add_kernel(CLI::App& app, KernelFlags& f) {
  auto* kernel = app.add_subcommand("kernel", "Frequency and step response of a kernel, as JSON (or CSV)");
  kernel->add_option("--filter", f.filter, "Kernel NAME[:k=v,...]")->required();
  kernel->add_flag("--response", f.a.response, "Include K(f) for f in [0, 2] (CSV: the f,K table)");
  kernel->add_flag("--step", f.a.step, "Include the step response (CSV: the x,S table)");
  kernel->add_flag("--csv", f.a.csv, "Print a CSV table instead of JSON (x,k by default)");
  return kernel;
}

int kernel(KernelFlags& f) {
  f.a.filter = fest::sampling::make_kernel(f.filter);
  return run_kernel(f.a);
}

struct ChainFlags {
  ChainArgs a;
  std::string prefilter, recon;
};

CLI::App* add_chain1d(CLI::App& app, ChainFlags& f) {
  ChainArgs& ch = f.a;
  auto* chain = app.add_subcommand("chain1d", "1-D prefilter -> sample -> display analysis (Fig. 10.10, 10.2), as JSON");
  chain->add_option("--prefilter", f.prefilter, "Prefilter kernel (ideal, dual:R, ...)");
  chain->add_option("--recon", f.recon, "Display reconstruction kernel");
  chain->add_option("--freq", ch.freq, "Signal frequencies in cycles per sample, comma-separated")->delimiter(',')->allow_extra_args(false);
  chain->add_option("--edge", ch.edge, "Fig. 10.2: step at x0, or bar x0,x1")->delimiter(',')->allow_extra_args(false);
  chain->add_option("--terms", ch.terms, "Alias terms K (k = -K..K)")->default_val(2000)->check(fest::cli::range(1, 1000000));
  return chain;
}

int chain1d(ChainFlags& f) {
  ChainArgs& ch = f.a;
  if (ch.freq.empty() == ch.edge.empty()) throw fest::usage_error("chain1d needs exactly one of --freq and --edge");
  if (!ch.freq.empty()) {  // the edge experiment of Fig. 10.2 has its own kernels
    if (f.prefilter.empty() || f.recon.empty()) throw fest::usage_error("chain1d --freq needs --prefilter and --recon");
    ch.prefilter = fest::sampling::make_kernel(f.prefilter);
    ch.recon = fest::sampling::make_kernel(f.recon);
  }
  return run_chain1d(ch);
}

struct MipKernelFlags {
  MipKernelArgs a;
  std::string build = "box";
};

CLI::App* add_mipkernel(CLI::App& app, MipKernelFlags& f) {
  MipKernelArgs& mk = f.a;
  auto* mipkernel = app.add_subcommand("mipkernel", "The level-0 weights of one mip-map lookup (Fig. 10.12/10.13), as CSV");
  mipkernel->add_option("--level", mk.level, "Level L (fractional: trilinear blend)")->required();
  mipkernel->add_option("--pos", mk.pos, "Positions x in level-0 texels (--dims 2: x,y)")->delimiter(',')->allow_extra_args(false)->required();
  mipkernel->add_option("--build", f.build, "Pyramid build: box, gaussian")->default_val("box");
  mipkernel->add_option("--dims", mk.dims, "1 or 2")->default_val(1)->check(fest::cli::range(1, 2));
  return mipkernel;
}

int mipkernel(MipKernelFlags& f) {
  f.a.build = fest::sampling::parse_mip_build(f.build);
  return run_mipkernel(f.a);
}

struct MetricsFlags {
  MetricsArgs a;
  std::string zoneplate;
};

CLI::App* add_metrics(CLI::App& app, MetricsFlags& f) {
  MetricsArgs& mt = f.a;
  auto* metrics = app.add_subcommand("metrics", "RMSE/PSNR against a reference and zone-plate aliasing, as JSON");
  metrics->add_option("input", mt.input, "Test image, or - for standard input")->default_val("-");
  metrics->add_option("--ref", mt.ref, "Reference image");
  metrics->add_option("--zoneplate", f.zoneplate, "The image is a zone plate: numax=1[,width=W,height=H]")->expected(0, 1)->default_str("");
  metrics->add_option("--alias-band", mt.alias_band, "Alias band lo,hi (cycles/pixel)")->delimiter(',')->allow_extra_args(false);
  metrics->add_option("--pass-band", mt.pass_band, "Pass band lo,hi (cycles/pixel)")->delimiter(',')->allow_extra_args(false);
  metrics->add_option("--mask", mt.mask, "One-channel image: compare where non-zero");
  fest::cli::enum_words<MetricsDomain>(metrics->add_option("--domain", mt.domain, "linear or encoded"),
                        {{"linear", MetricsDomain::linear}, {"encoded", MetricsDomain::encoded}})->default_str("linear");
  metrics->add_flag("--spectrum", mt.spectrum, "Add the horizontal power spectrum (f, power)");
  metrics->add_option("--beat", mt.beat, "f1,f2 in cycles per pixel: add the power at |f1 - f2| (the beat of §10.4.4)")
      ->delimiter(',')->allow_extra_args(false);
  return metrics;
}

int metrics(CLI::App& sub, MetricsFlags& f) {
  const bool zoneplate = sub.count("--zoneplate") > 0 || !f.zoneplate.empty();
  check_metrics_args(f.a, zoneplate);  // before the zone plate's text is read
  if (zoneplate) f.a.zoneplate = zone_plate(f.zoneplate == "-" ? "" : f.zoneplate);
  return run_metrics(f.a);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Prefiltering, sampling and reconstruction: resize images with a choice of kernels in linear light,\n"
               "render analytic test scenes, inspect kernels, and measure aliasing.",
               "resample"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  ResizeFlags rz;
  DisplayFlags dp;
  MipFlags mp;
  RenderFlags rd;
  TextureFlags tx;
  NormalMipArgs nm;
  KernelFlags kn;
  ChainFlags ch;
  MipKernelFlags mk;
  MetricsFlags mt;
  auto* resize_cmd = add_resize(app, rz);
  auto* display_cmd = add_display(app, dp);
  auto* mip_cmd = add_mip(app, mp);
  auto* render_cmd = add_render(app, rd);
  auto* texture_cmd = add_texture(app, tx);
  auto* normalmip_cmd = add_normalmip(app, nm);
  auto* kernel_cmd = add_kernel(app, kn);
  auto* chain_cmd = add_chain1d(app, ch);
  auto* mipkernel_cmd = add_mipkernel(app, mk);
  auto* metrics_cmd = add_metrics(app, mt);

  return fest::cli::run(app, argc, argv, [&] {
    if (*resize_cmd) return resize(rz);
    if (*display_cmd) return display(dp);
    if (*mip_cmd) return mip(mp);
    if (*render_cmd) return render(rd);
    if (*normalmip_cmd) return run_normalmip(nm);
    if (*texture_cmd) return texture(tx);
    if (*kernel_cmd) return kernel(kn);
    if (*chain_cmd) return chain1d(ch);
    if (*mipkernel_cmd) return mipkernel(mk);
    if (*metrics_cmd) return metrics(*metrics_cmd, mt);
    throw fest::usage_error("no subcommand");
  });
}
