#pragma once
// volrender's input volume: read (formats/volume_source), checked (2 samples per axis, no
// NaN) and made a float grid with its value range; one frame, or every frame in turn.

#include <optional>
#include <string>

#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::volrender_tool {

struct LoadedVolume {
  volume_pyramid::ScalarGrid grid;
  double lo = 0, hi = 1;  // value range
  std::string name;       // the input's name for messages
};

// One volume (frame `options.frame` of a stream or series). Throws bad_input for an empty
// input, fewer than 2 samples along an axis, or NaN samples.
LoadedVolume load_volume(const std::string& path, const formats::VolumeSourceOptions& options);

// Frame t of an input's frames, checked like load_volume.
LoadedVolume load_frame(const formats::VolumeFrames& frames, std::size_t t, const std::string& name);

}  // namespace fest::volrender_tool
