// markerpose: square fiducial markers in camera images -> IDs, sub-pixel corners and the
// 6-DoF pose relative to the camera (the MagicBook's registration, Kato & Billinghurst
// 1999; docs/markerpose.md). Wiring only: this file maps flags onto commands.hpp.

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "cli/implied_subcommand.hpp"
#include "commands.hpp"

using namespace fest::markerpose_tool;

namespace {

// Adds the flags of `detect` to `cmd`; returns them so that main can tell whether any was given.
std::vector<CLI::Option*> add_detect_flags(CLI::App& cmd, DetectOptions& det) {
  std::vector<CLI::Option*> o;
  o.push_back(cmd.add_option("images", det.inputs, "Images; - or nothing: standard input (one image or a PNG/PGM stream)"));
  o.push_back(cmd.add_option("--list", det.list, "A file naming one image per line"));
  o.push_back(cmd.add_option("--camera", det.camera, "Intrinsics and distortion: the camera.json of capture calib-camera"));
  o.push_back(cmd.add_option("--size", det.size, "Marker side (outer edge of the black border); tvec comes in its unit"));
  o.push_back(cmd.add_option("--dict", det.dict, "Dictionary: 4x4_50 ... 7x7_1000, aruco_original, apriltag_16h5/25h9/36h10/36h11"));
  o.push_back(cmd.add_option("--pattern", det.patterns, "ARToolKit pattern picture (repeatable; id = position); replaces --dict"));
  o.push_back(cmd.add_option("--min-ncc", det.min_ncc, "Pattern markers: correlation needed")->check(fest::cli::range(0.0, 1.0)));
  o.push_back(cmd.add_option("--min-side", det.min_side_px, "Smallest marker side searched, pixels")->check(fest::cli::range(4.0, 1e5)));
  o.push_back(cmd.add_option("--overlay", det.overlay, "Mesh (PLY, OBJ, OFF, STL) drawn at every marker pose, in the marker frame"));
  o.push_back(cmd.add_option("--overlay-out", det.overlay_out, "The overlay image (PNG); with %d for several frames"));
  o.push_back(cmd.add_option("--overlay-scale", det.overlay_scale, "Mesh units -> marker units")->check(fest::cli::positive));
  o.push_back(cmd.add_option("-o,--output", det.output, "JSON output (- = standard output)"));
  o.push_back(cmd.add_flag("--lines", det.lines, "JSON lines even for a single image"));
  o.push_back(cmd.add_option("--report", det.report, "Counts and detection time as JSON"));
  fest::cli::add_threads(cmd, det.threads);
  o.push_back(cmd.get_option("--threads"));
  fest::cli::add_progress(cmd, det.progress);
  o.push_back(cmd.get_option("--progress"));
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Square fiducial markers (ArUco/AprilTag codes or ARToolKit patterns) in camera images:\n"
               "IDs, sub-pixel corners and the marker's pose relative to the camera.",
               "markerpose"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);

  // `markerpose IMAGE ...` means `markerpose detect IMAGE ...`: the main command takes
  // detect's flags too, and detects when no subcommand is named.
  DetectOptions det;
  fest::cli::imply_subcommand(app, add_detect_flags(app, det), "Options of detect (also without the word detect)",
                              {"--camera", "--size"}, false);
  CLI::App* d = app.add_subcommand("detect", "Find markers and their poses (the default subcommand)");
  add_detect_flags(*d, det);
  d->get_option("--camera")->required();
  d->get_option("--size")->required();

  GenOptions gen;
  CLI::App* g = app.add_subcommand("gen", "Synthetic marker image(s) at a known pose, with the ground truth");
  g->add_option("--camera", gen.camera, "camera.json (else --width, --height, --focal)");
  g->add_option("--width", gen.width, "Image width")->check(fest::cli::range(16, 16384));
  g->add_option("--height", gen.height, "Image height")->check(fest::cli::range(16, 16384));
  g->add_option("--focal", gen.focal, "Focal length, pixels")->check(fest::cli::positive);
  g->add_option("--dict", gen.dict, "Dictionary of the marker");
  g->add_option("--id", gen.id, "Marker id")->check(fest::cli::non_negative);
  g->add_option("--pattern", gen.pattern, "Draw an ARToolKit pattern marker with this picture instead");
  g->add_option("--size", gen.size, "Marker side (length unit of the pose)");
  g->add_option("--u", gen.u, "Image x of the marker centre (default: principal point)");
  g->add_option("--v", gen.v, "Image y of the marker centre");
  g->add_option("--distance", gen.distance, "Distance of the marker centre from the camera");
  g->add_option("--tilt", gen.tilt, "Viewing angle off the marker normal, degrees")->check(fest::cli::range(0.0, 89.0));
  g->add_option("--axis", gen.axis, "Direction of the tilt axis in the marker plane, degrees");
  g->add_option("--roll", gen.roll, "Rotation about the marker normal, degrees");
  g->add_option("--frames", gen.frames, "Number of frames")->check(fest::cli::range(1, 100000));
  g->add_option("--tilt-step", gen.tilt_step, "Tilt change per frame, degrees");
  g->add_option("--roll-step", gen.roll_step, "Roll change per frame, degrees");
  g->add_option("--u-step", gen.u_step, "Horizontal motion per frame, pixels");
  g->add_option("--black", gen.black, "Grey level of the print's black")->check(fest::cli::range(0.0, 255.0));
  g->add_option("--white", gen.white, "Grey level of the print's white")->check(fest::cli::range(0.0, 255.0));
  g->add_option("--gradient", gen.gradient, "Illumination gain change across the image")->check(fest::cli::range(0.0, 1.0));
  g->add_option("--occlusion", gen.occlusion, "Fraction of the marker interior covered")->check(fest::cli::range(0.0, 1.0));
  g->add_option("--blur", gen.blur, "Gaussian blur sigma, pixels")->check(fest::cli::range(0.0, 50.0));
  g->add_option("--noise", gen.noise, "Gaussian noise sigma, grey levels")->check(fest::cli::range(0.0, 100.0));
  g->add_flag("!--no-clutter", gen.clutter, "Plain background instead of a textured, cluttered one");
  g->add_option("--background", gen.background, "A photograph of the camera's size as the background");
  g->add_option("--seed", gen.seed, "Random seed (background, noise, occluder)");
  g->add_option("-o,--output", gen.output, "Image; several frames: a name with %d, or one PNG/PGM stream");
  std::string gen_to;
  g->add_option("--to", gen_to, "png or pgm")->check(CLI::IsMember({"png", "pgm"}));
  g->add_option("--truth", gen.truth, "Ground truth JSON (corners, rvec, tvec, R, side_px)");

  DrawOptions draw;
  CLI::App* w = app.add_subcommand("draw", "A printable marker image (PNG)");
  w->add_option("--dict", draw.dict, "Dictionary");
  w->add_option("--id", draw.id, "Marker id")->check(fest::cli::non_negative);
  w->add_option("--cell", draw.cell_px, "Pixels per cell")->check(fest::cli::range(1, 1000));
  w->add_option("--quiet-zone", draw.quiet_cells, "White cells around the border")->check(fest::cli::range(0, 100));
  w->add_option("-o,--output", draw.output, "Output image (- = PNG on standard output)");

  return fest::cli::run(app, argc, argv, [&] {
    if (*g) {
      if (!gen_to.empty()) gen.to = fest::formats::output_format_from_name(gen_to).format;
      return gen_command(gen);
    }
    if (*w) return draw_command(draw);
    det.quiet = common.quiet;  // detect, named or implied
    return detect_command(det);
  });
}
