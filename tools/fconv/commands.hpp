#pragma once
// fconv's jobs (docs/fconv.md), each taking its typed options. main.cpp fills these from
// flags; everything else in this folder is the fest_fconv_app library.

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "core/volume.hpp"
#include "core/volume_view.hpp"
#include "formats/detect.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::fconv_tool {

// Convert a file to another format of the same kind.
struct ConvertOptions {
  std::string input = "-";
  std::string output = "-";
  // The output format: this, else the output file's extension, else (standard output)
  // the input's own format.
  std::optional<formats::OutputFormat> to;
  bool ascii = false;     // text variant where the format has one
  bool compress = false;  // NRRD (gzip) and MHA (zlib) data
  bool half = false;      // EXR half channels
  bool progress = false;  // --progress: a bar while a large PNG is deflated
  int quality = 95;       // JPEG output (formats::default_jpeg_quality)
  bool flatten = false;   // --flatten / --background: alpha composited for PGM/PPM/JPEG output
  std::array<double, 3> background{1, 1, 1};  // display values 0-1
  std::optional<ScalarType> volume_type;  // volumes: store values as this type
  bool rescale = false;                   // map the value range onto volume_type's
  std::optional<std::size_t> frame;       // volumes: only this frame of a 4-D series
  int draco_bits = 11;          // draco_encoder's -qp default
  int draco_normal_bits = 8;    // -qn
  int draco_texcoord_bits = 10; // -qt
  int draco_speed = 3;          // 10 - draco_encoder's -cl (default 7)
  formats::CoordinatePrecision precision = formats::CoordinatePrecision::automatic;
  bool drop_unrepresentable = false;
  // A volume (or VTK image data, frame stream) to an image format: a quick look
  // (docs/fconv.md "Volume quick look"). view is set only when --view was given.
  std::optional<VolumeViewKind> view;
  std::optional<std::array<std::size_t, 3>> slice;
  std::optional<std::array<double, 2>> window;
  DisplayConvention convention = DisplayConvention::neurological;
  bool verbose = false;  // describe the picture's panels on standard error
};

// Describe a file as JSON (--info).
struct InfoOptions {
  std::string input = "-";
  std::string output = "-";
};

int convert_command(const ConvertOptions& o);
int info_command(const InfoOptions& o);

}  // namespace fest::fconv_tool
