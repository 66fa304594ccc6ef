#pragma once
// The subcommands of resample (docs/resample.md): option structs filled by main.cpp's CLI11
// parser, and one function per subcommand that wires formats -> lib/sampling -> output.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats/detect.hpp"

#include "sampling/display_model.hpp"
#include "sampling/kernel.hpp"
#include "sampling/mip_kernel.hpp"
#include "sampling/resize.hpp"
#include "sampling/sample_patterns.hpp"
#include "sampling/texture.hpp"

namespace fest::resample_tool {

// --depth: the output's samples (f16: EXR half floats).
enum class OutputDepth { u8, u16, f16, f32 };

struct ImageOutput {
  std::string output = "-";
  std::optional<formats::OutputFormat> to;  // --to / --format; none: -o's extension, else PNG/PFM
  std::optional<OutputDepth> depth;         // none: what the format and the image hold
  int quality = 95;                         // --quality: JPEG output, 1-100 (formats::default_jpeg_quality)
  bool flatten = false;                     // --flatten / --background: alpha composited for PGM/PPM/JPEG
  std::array<double, 3> background{1, 1, 1};  // display values 0-1 (--background codes / 255)
  bool progress = false;                    // --progress: a bar while a large PNG is deflated
};

// --colorspace of resize: what the stored numbers are (automatic: as the file says), or
// codes: filter the stored numbers themselves, not linear light.
enum class ResizeColor { automatic, srgb, linear, codes };
// --alpha of resize: premultiply before filtering, filter straight, or no alpha handling.
enum class AlphaMode { premul, straight, none };
// --colorspace of render's integer output: sRGB codes, or the plain linear values.
enum class RenderColor { srgb, linear };
// --filter of mip and --mip of texture: the kernel that halves each level.
using MipFilter = sampling::PyramidFilter;
// --domain of metrics: compare linear-light values or the encoded numbers.
enum class MetricsDomain { linear, encoded };

struct ResizeArgs {
  std::string input = "-";
  ImageOutput out;
  std::optional<std::pair<int, int>> size;  // --size WxH
  int width = 0, height = 0;        // --width / --height (the other keeps the aspect)
  std::vector<double> scale;        // S or Sx,Sy
  sampling::Kernel filter = sampling::make_kernel("mitchell");
  std::vector<double> shift;        // dx,dy in input pixels
  sampling::EdgeMode edge = sampling::EdgeMode::clamp;
  ResizeColor colorspace = ResizeColor::automatic;
  AlphaMode alpha = AlphaMode::premul;
  sampling::ClampMode clamp = sampling::ClampMode::automatic;  // automatic: range for integer output
  bool hicomp = false, dither = false;
  unsigned long long seed = 1;
  int threads = 0;
};

struct DisplayArgs {
  std::string input = "-";
  ImageOutput out;
  sampling::DisplayModel model = sampling::make_display_model("lcd");
  int factor = 8;  // in [1, 64] (main.cpp checks it first)
  int threads = 0;
};

struct MipArgs {
  std::string input = "-";
  std::string prefix;  // not empty (main.cpp checks it first)
  MipFilter filter = MipFilter::box;
  int levels = 0;  // 0: down to 1x1
  std::optional<formats::OutputFormat> to;  // none: EXR for float images, else PNG
  int threads = 0;
};

struct RenderArgs {
  ImageOutput out;
  std::string scene = "zoneplate";
  std::map<std::string, double> params;  // scene parameters (--param key=value)
  int width = 256, height = 256;
  int spp = 16;
  sampling::Pattern pattern = sampling::Pattern::jitter;  // not used with ground_truth
  // --pixel-filter for every scene but point: the kernel, stretched by filter_scale to the
  // radius asked for.
  sampling::Kernel pixel_filter = sampling::make_kernel("box");
  double filter_scale = 1;
  // --pixel-filter for --scene point: lowpass, bandpass (its lo is in params) or a kernel
  // name, as sampling::make_scene takes it.
  std::string point_filter = "lowpass";
  unsigned long long seed = 1;
  bool ground_truth = false;
  int gt_spp = 4096;
  RenderColor colorspace = RenderColor::srgb;
  int threads = 0;
};

struct KernelArgs {
  sampling::Kernel filter;
  bool response = false, step = false, csv = false;
  std::string output = "-";
};

// Exactly one of freq (with prefilter and recon) and edge (main.cpp checks that first).
struct ChainArgs {
  sampling::Kernel prefilter, recon;
  std::vector<double> freq, edge;
  int terms = 2000;
  bool amplitudes = false;
};

struct MipKernelArgs {
  double level = 0;
  std::vector<double> pos;
  sampling::MipBuild build = sampling::MipBuild::box;
  int dims = 1;
};

// metrics --zoneplate numax=1[,width=W,height=H]: the zone plate the image shows (width
// and height 0: the image's own).
struct ZonePlate {
  double numax = 1;
  int width = 0, height = 0;
};

struct MetricsArgs {
  std::string input = "-";
  std::string ref;
  std::optional<ZonePlate> zoneplate;  // the image is a zone plate
  std::vector<double> alias_band{0.6, 1.0}, pass_band{0.0, 0.2};
  std::string mask;
  MetricsDomain domain = MetricsDomain::linear;
  bool spectrum = false;
  std::vector<double> beat;  // f1,f2: report the power at |f1 − f2|
};

// texture --map plane:h=1,pitch=10,fov=60,period=1: the ground plane z = 0 seen by a
// pinhole camera at height h, pitched down by `pitch` degrees, vertical field of view
// `fov` degrees; the texture repeats every `period` world units (sampling::plane_map).
struct PlaneView {
  double h = 1, pitch = 10, fov = 60, period = 1;
};

struct TextureArgs {
  ImageOutput out;
  std::string tex;
  std::optional<PlaneView> map;  // exactly one of map and uv
  std::string uv;                // a 2-channel image of texture coordinates
  int width = 512, height = 384;
  sampling::TextureOptions method;  // its lod_bias and threads come from the fields below
  MipFilter mip = MipFilter::box;
  double lod_bias = 0;
  bool ground_truth = false;
  double aniso_mask = 0;  // > 0: write the mask of pixels whose anisotropy exceeds it
  unsigned long long seed = 1;
  int threads = 0;
};

// Needs tex and exactly one of map and uv (main.cpp checks them first).
int run_texture(const TextureArgs& a);

struct NormalMipArgs {
  std::string input = "-";
  std::string prefix;
  bool normal_map = false, height_map = false, naive = false;
  double height_scale = 1;
  int threads = 0;
};

int run_normalmip(const NormalMipArgs& a);

int run_resize(const ResizeArgs& a);
int run_display(const DisplayArgs& a);
int run_mip(const MipArgs& a);
int run_render(const RenderArgs& a);
int run_kernel(const KernelArgs& a);
int run_chain1d(const ChainArgs& a);
int run_mipkernel(const MipKernelArgs& a);
// Usage errors for a metrics request that asks for nothing or gives malformed pairs
// (zoneplate: whether --zoneplate was given); run_metrics checks them first too.
void check_metrics_args(const MetricsArgs& a, bool zoneplate);
int run_metrics(const MetricsArgs& a);

}  // namespace fest::resample_tool
