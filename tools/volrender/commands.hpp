#pragma once
// volrender's command library (fest_volrender_app): typed options and one function per
// subcommand; main.cpp only fills these from the flags.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "formats/volume_source/volume_source.hpp"
#include "raycast/render.hpp"
#include "raycast/screen_polygon.hpp"
#include "raycast/transfer_function.hpp"
#include "raycast/vec3.hpp"

namespace fest::volrender_tool {

enum class StereoLayout { files, sbs, tb, anaglyph };

struct CameraArgs {
  int width = 512, height = 512;                 // --size WxH
  std::vector<double> view{0, 0};                // AZ,EL[,ROLL] degrees (orbit)
  double zoom = 1.0;
  std::optional<double> fov;                     // degrees; orbit default 30, 0 = orthographic
  std::optional<raycast::Vec3> eye, look_at;
  raycast::Vec3 up{0, 0, 1};
  std::vector<raycast::Vec3> screen;             // off-axis screen corners PA, PB, PC (empty = none)
  double near = 0;
  std::optional<std::array<double, 4>> mirror;   // NX,NY,NZ,DELTA
  std::vector<raycast::Vec3> mirror_poly;        // the mirror's outline
  std::optional<double> stereo;                  // eye separation (world units)
  StereoLayout stereo_layout = StereoLayout::files;
  std::optional<raycast::Vec3> head_right;       // default: the screen's / camera's right
};

enum class Gradients { otf, cache, automatic };  // automatic: cache up to 64 M voxels

// --slice-axis: an index axis (0, 1, 2 = x, y, z) or a world normal.
struct SliceAxis {
  int index_axis = 2;
  std::optional<raycast::Vec3> normal;
};

// --contours c0:dc:n
struct Contours {
  double c0 = 0, dc = 0, count = 0;
};

struct RenderArgs {
  raycast::Mode mode = raycast::Mode::dvr;
  std::string input = "-";
  std::string output = "-";        // with --all-frames: a pattern with %d (e.g. %05d)
  std::string to;                  // png | pfm | exr ("" = from -o, else png)
  std::string field;
  formats::VectorComponent component = formats::VectorComponent::mag;
  long frame = -1;                 // -1 = the last
  bool all_frames = false;         // --frame all: one image per frame
  std::optional<formats::RawLayout> raw;  // --raw: the input is a headerless volume
  int spp = 1;
  bool keep_alpha = false;         // --bg none
  std::array<double, 3> background{0, 0, 0};
  bool linear = false;
  std::string depth_image;
  double step = 0.5;
  bool jitter = false;
  bool nearest = false;            // --interp nearest
  std::string tf;                  // file or preset ("" = grey for dvr, contour-only for slices)
  raycast::OpacityMode tf_mode = raycast::OpacityMode::opacity;
  double tf_unit = 1.0;
  bool preint = false;
  bool shade = false;
  std::array<double, 4> phong{0.3, 0.7, 0.2, 20};
  bool two_sided = false;
  double ert = 0.995;
  std::optional<std::array<double, 2>> window;
  std::vector<raycast::IsoLayer> isos;
  bool no_skip = false;
  Gradients gradients = Gradients::automatic;
  int threads = 0;
  bool progress = false;  // --progress: tiles cast, over every image
  SliceAxis slice_axis;
  int slice_count = 8;
  std::vector<double> slice_at;
  std::optional<Contours> contours;
  double contour_width = 1, contour_alpha = 1;
  std::optional<double> contour_width_world;  // world units; replaces contour_width
  bool slice_frame = false;                   // outline each plane (one smallest spacing wide)
  std::string mesh;                // opaque triangle mesh composited with depth
  std::array<double, 3> mesh_color{0.9, 0.85, 0.75};
  std::string screen_mask;         // PNG: cast only the pixels it marks
  std::vector<raycast::ScreenPoint> screen_polygon;  // or: cast only the pixels whose centres it holds
  std::string camera_json, report;
  CameraArgs camera;
};

struct CameraPrintArgs {
  CameraArgs camera;
  std::string input;  // optional volume (orbit cameras need its bounds)
  std::optional<formats::RawLayout> raw;
};

struct CompositeArgs {
  std::vector<std::string> inputs;  // top first
  std::string output = "-";
};

int run_render(const RenderArgs& args);
// Stacks the images with "over" (the first on top) in linear light; 8-bit sRGB PNG out.
int run_composite(const CompositeArgs& args);
int run_camera_print(const CameraPrintArgs& args);

}  // namespace fest::volrender_tool
