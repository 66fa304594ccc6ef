#pragma once
// markerpose's commands (docs/markerpose.md): typed options and one function per
// subcommand. main.cpp maps flags onto these; tests and benchmarks link the library
// fest_markerpose_app.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "formats/detect.hpp"

namespace fest::markerpose_tool {

// markerpose [detect] IMAGE... : markers and poses per frame.
struct DetectOptions {
  std::vector<std::string> inputs;  // images; "-" (or none): standard input, one image or a stream
  std::string list;                 // a file naming one image per line
  std::string camera;               // camera.json (capture calib-camera)
  double size = 0;                  // marker side (outer edge of the black border), any length unit
  std::string dict = "4x4_50";
  std::vector<std::string> patterns;  // ARToolKit pattern pictures (id = position); replaces --dict
  double min_ncc = 0.75;
  double min_side_px = 6;
  std::string overlay;              // mesh drawn at every marker pose
  std::string overlay_out;          // overlay image (PNG); %d = frame number for several frames
  double overlay_scale = 1;         // mesh units -> marker length units
  std::string output = "-";         // JSON (one image) or JSON lines (several)
  std::string report;
  bool lines = false;               // JSON lines even for one image
  int threads = 0;
  bool progress = false;  // --progress: frames searched for markers
  bool quiet = false;
};
int detect_command(const DetectOptions& o);

// markerpose gen: a synthetic scene with its ground truth.
struct GenOptions {
  std::string camera;  // camera.json; else --width/--height/--focal
  int width = 640, height = 480;
  double focal = 600;
  std::string dict = "4x4_50";
  std::string pattern;  // a pattern picture instead of a dictionary marker
  int id = 0;
  double size = 0.05;
  double u = -1, v = -1;  // image point of the marker centre (default: the principal point)
  double distance = 0.3;
  double tilt = 30, axis = 0, roll = 0;    // degrees
  double tilt_step = 0, roll_step = 0, u_step = 0;  // per frame
  int frames = 1;
  double black = 20, white = 235, gradient = 0, occlusion = 0, blur = 0, noise = 0;
  bool clutter = true;
  std::string background;  // a photograph (the camera's size) instead of the synthetic background
  std::uint64_t seed = 1;
  std::string output = "-";  // image; several frames: a pattern with %d, or one stream (PNG/PGM)
  std::optional<formats::Format> to;  // --to png|pgm (standard output / stream); none: from -o, else PGM
  std::string truth;         // ground-truth JSON (lines for several frames)
};
int gen_command(const GenOptions& o);

// markerpose draw: a printable marker.
struct DrawOptions {
  std::string dict = "4x4_50";
  int id = 0;
  int cell_px = 20;
  int quiet_cells = 1;
  std::string output = "-";
};
int draw_command(const DrawOptions& o);

}  // namespace fest::markerpose_tool
