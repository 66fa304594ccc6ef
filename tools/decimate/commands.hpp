#pragma once
// decimate's command library (fest_decimate_app): read a mesh with formats/, simplify it
// with lib/decimate, measure the result against the input with lib/compare (the metric
// behind fcompare, independent of the simplifier's own quadric estimate), write it.

#include <cstddef>
#include <string>

#include "decimate/simplify.hpp"

namespace fest::decimate_tool {

struct Options {
  std::string input = "-";
  std::string output = "-";
  std::string to;                 // output format name; default: -o's extension, else the input's
  std::size_t faces = 0;          // target face count
  double ratio = 0;               // target as a fraction of the input faces (0 < r <= 1)
  double error = -1;              // error bound, absolute length
  double error_rel = -1;          // error bound as a fraction of the bbox diagonal
  bool lock_boundary = false;     // --lock boundary
  bool lock_features = false;     // --lock features
  double feature_angle = 180;     // degrees
  bool no_attributes = false;
  double attribute_weight = 1.0;
  bool optimal_placement = true;  // --placement optimal (quadric minimiser), else vertex
  decimate::Weighting weighting = decimate::Weighting::sqrt_area;
  bool drop_nonmanifold = false;
  bool ascii = false;
  std::string report;             // JSON with counts, time, Hausdorff and RMS
  std::size_t samples = 100000;   // extra surface samples of the measurement
  int threads = 0;
  bool quiet = false;
  bool progress = false;  // --progress: faces removed
};

int run(const Options& options);

}  // namespace fest::decimate_tool
