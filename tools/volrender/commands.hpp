#pragma once
// volrender's command library (fest_volrender_app): typed options and one function per
// subcommand; main.cpp only fills these from the flags.

#include <optional>
#include <string>
#include <vector>

namespace fest::volrender {

struct CameraArgs {
  std::string size = "512x512";
  std::string view = "0,0";        // AZ,EL[,ROLL] degrees (orbit)
  double zoom = 1.0;
  std::optional<double> fov;       // degrees; orbit default 30, 0 = orthographic
  std::string eye, look_at, up = "0,0,1";
  std::string screen;              // "PA;PB;PC" off-axis screen corners
  double near = 0;
  std::string mirror;              // "NX,NY,NZ,DELTA"
  std::string mirror_poly;         // "x,y,z;x,y,z;..."
  std::optional<double> stereo;    // eye separation (world units)
  std::string stereo_layout = "files";  // files | sbs | tb | anaglyph
  std::string head_right;          // default: the screen's / camera's right
};

struct RenderArgs {
  std::string mode = "dvr";        // dvr | mip | minip | avg | iso | slices
  std::string input = "-";
  std::string output = "-";
  std::string to;                  // png | pfm | exr
  std::string field, component = "mag";
  long frame = -1;
  int spp = 1;
  std::string bg = "0,0,0";
  bool linear = false;
  std::string depth_image;
  double step = 0.5;
  bool jitter = false;
  std::string interp = "trilinear";
  std::string tf;                  // file or preset ("" = grey for dvr)
  std::string tf_mode = "opacity";
  double tf_unit = 1.0;
  bool preint = false;
  std::string shade = "off";
  std::string phong = "0.3,0.7,0.2,20";
  bool two_sided = false;
  double ert = 0.995;
  std::string window;
  std::string iso, iso_color;
  bool no_skip = false;
  std::string gradients = "auto";  // otf | cache | auto (cache up to 64 M voxels)
  int threads = 0;
  std::string slice_axis = "z";     // x | y | z | nx,ny,nz
  int slice_count = 8;
  std::string slice_at, contours;
  double contour_width = 1, contour_alpha = 1;
  std::optional<double> contour_width_world;  // world units; replaces contour_width
  bool slice_frame = false;                   // outline each plane (one smallest spacing wide)
  std::string mesh;                // opaque triangle mesh composited with depth
  std::string mesh_color = "0.9,0.85,0.75";
  std::string camera_json, report;
  CameraArgs camera;
};

struct CameraPrintArgs {
  CameraArgs camera;
  std::string input;  // optional volume (orbit cameras need its bounds)
};

struct CompositeArgs {
  std::vector<std::string> inputs;  // top first
  std::string output = "-";
};

int run_render(const RenderArgs& args);
// Stacks the images with "over" (the first on top) in linear light; 8-bit sRGB PNG out.
int run_composite(const CompositeArgs& args);
int run_camera_print(const CameraPrintArgs& args);

}  // namespace fest::volrender
