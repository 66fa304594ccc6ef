#include "volume_input.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"

namespace fest::volrender_tool {
namespace {

LoadedVolume checked(const Volume& v, const std::string& name) {
  LoadedVolume L;
  L.name = name;
  for (int ax = 0; ax < 3; ++ax)
    if (v.dims[ax] < 2) throw bad_input("volume is {}x{}x{}: ray casting needs 2 samples along every axis ({})", v.dims[0], v.dims[1], v.dims[2], L.name);
  std::size_t nans = 0;
  L.grid = volume_pyramid::to_grid(v, nans);
  if (nans) throw bad_input("{} NaN samples ({})", nans, L.name);
  float lo = L.grid.values[0], hi = lo;
  for (float x : L.grid.values) lo = std::min(lo, x), hi = std::max(hi, x);
  L.lo = lo, L.hi = hi;
  return L;
}

}  // namespace

LoadedVolume load_volume(const std::string& path, const formats::VolumeSourceOptions& options) {
  const std::string name = input_name(path);
  formats::Input in = formats::load_volume_input(path, options);
  if (in.bytes.empty()) throw bad_input("empty input ({})", name);
  return checked(formats::read_volume_source(in, options), name);
}

LoadedVolume load_frame(const formats::VolumeFrames& frames, std::size_t t, const std::string& name) {
  return checked(frames.frame(t), fmt::format("{}, frame {}", name, t));
}

}  // namespace fest::volrender_tool
