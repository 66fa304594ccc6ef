#pragma once
// hdrmerge --manifest (specs/capture.md §2.8): every (angle, light) set of a capture
// session merged into DIR/a{ai:03}_{light}.exr (R,G,B + "valid", with the exposures,
// response hash, angle and light in the header), every silhouette into
// DIR/a{ai:03}_mask.png, and the rig JSON for brdffit on standard output.

#include <string>

namespace fest::hdrmerge_tool {

struct ManifestArgs {
  std::string manifest = "-";
  std::string output_dir;     // default SESSION/hdr
  std::string response_in;    // a response CSV; default: recovered from the first set
  std::string method = "debevec";
  int samples = 1000;
  double lambda = 10;
  bool full_float = false;
  int threads = 0;
};

int run_manifest(const ManifestArgs& args);

}  // namespace fest::hdrmerge_tool
