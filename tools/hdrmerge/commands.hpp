#pragma once
// hdrmerge's subcommands (docs/hdrmerge.md), each taking its typed options. main.cpp fills
// these from flags; everything else in this folder is the fest_hdrmerge_app library.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "formats/detect.hpp"
#include "hdr/bracket.hpp"
#include "hdr/debevec.hpp"

namespace fest::hdrmerge_tool {

// How the camera response is recovered from an exposure series.
enum class Method { debevec, robertson };

struct SeriesOptions {
  std::vector<std::string> images;
  std::vector<double> times;  // seconds, one per image
  int samples = hdr::DebevecOptions{}.samples;
  double lambda = hdr::DebevecOptions{}.lambda;
  Method method = Method::debevec;
};

struct MergeOptions {
  SeriesOptions series;
  std::string output = "-";
  std::optional<formats::Format> to;  // exr or pfm; default from the output's name
  bool full_float = false;
  std::string response_in, response_out, valid_out;
  int threads = 0;
  bool progress = false;  // --progress: images read, response, merge, encoding
};

struct CalibrateOptions {
  SeriesOptions series;
  std::string output = "-";
  bool progress = false;  // --progress: images read, then the recovery
};

struct BracketOptions {
  std::string radiance;
  std::vector<double> times;  // seconds
  hdr::CameraModel camera;
  double scale = 1;
  std::uint64_t seed = 1;
  std::string directory;
  std::string response_out;
  bool progress = false;  // --progress: exposures made and encoded
};

struct SheetOptions {
  std::vector<std::string> images;
  std::string output;
  int columns = 6;
  int width = 160;
};

// hdrmerge session (also `hdrmerge --manifest M`): every (angle, light) set of a capture
// session merged into DIR/a{ai:03}_{light}.exr (R,G,B + "valid", with the exposures,
// response hash, angle and light in the header), every silhouette into
// DIR/a{ai:03}_mask.png, and the rig JSON for brdffit on standard output.
struct SessionOptions {
  std::string manifest = "-";
  std::string output_dir;     // default SESSION/hdr
  std::string response_in;    // a response CSV; default: recovered from the first set
  Method method = Method::debevec;
  int samples = 1000;
  double lambda = 10;
  bool full_float = false;
  int threads = 0;
  bool progress = false;  // --progress: sets and masks written
};

int run_merge(const MergeOptions& o);
int run_calibrate(const CalibrateOptions& o);
int run_bracket(const BracketOptions& o);
int run_sheet(const SheetOptions& o);
int run_session(const SessionOptions& o);

}  // namespace fest::hdrmerge_tool
