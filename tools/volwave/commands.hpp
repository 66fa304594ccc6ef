#pragma once
// volwave's subcommands (docs/volwave.md §7), each taking its typed options. main.cpp
// fills these from flags; everything else in this folder is the fest_volwave_app library.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "wavelet/lifting.hpp"
#include "wavelet/vw_codec.hpp"

namespace fest::volwave_tool {

// Which scalar to take from inputs that hold several (VTI arrays, frame-stream fields,
// frames of a stream). "velocity.x" names one component of a vector field.
struct InputSelect {
  std::string field;
  long frame = -1;  // -1: the only frame
};

struct EncodeOptions {
  std::string input = "-";
  std::string output = "-";
  InputSelect select;
  std::optional<double> max_error;
  std::optional<double> rmse;
  bool lossless = false;
  wavelet::Wavelet wavelet = wavelet::Wavelet::cdf53;  // --wavelet haar|cdf53|cdf97
  double packed_slack = wavelet::kPackedSlackSpeed;    // --favour speed|size|SLACK (packed slabs)
  int levels = -1;
  std::vector<long> roi_box;  // x0,y0,z0,x1,y1,z1 voxel indices, inclusive
  std::string roi_mask;       // a volume; non-zero voxels are the region
  std::optional<double> roi_error;
  std::string report;
  int threads = 0;
  bool progress = false;  // --progress
  bool quiet = false;
};

struct DecodeOptions {
  std::string input = "-";
  std::string output = "-";
  std::string to;
  int chunks = -1;  // decode at most this many chunks (a coarser volume)
  std::string report;
  int threads = 0;
  bool progress = false;  // --progress
  bool quiet = false;
};

struct InfoOptions {
  std::string input = "-";
};

struct EdgesOptions {
  std::string input = "-";
  std::string output = "-";
  std::string to;
  InputSelect select;
  int scales = 3;
  double threshold = -1;   // modulus below this is no edge; < 0: automatic
  int min_scales = 0;      // chain length required (0: all scales)
  std::string points;      // CSV of sub-voxel edge points
  std::string report;
  int threads = 0;
  bool progress = false;  // --progress
};

int encode_command(const EncodeOptions& o);
int decode_command(const DecodeOptions& o);
int info_command(const InfoOptions& o);
int edges_command(const EdgesOptions& o);

}  // namespace fest::volwave_tool
