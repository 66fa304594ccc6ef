#pragma once
// Loads fest's VTK plugin (vtk_plugin_api.h) on first use, so that only a dataset read
// or written maps VTK into the process.

#include <cstddef>

namespace fest::formats::detail {

struct VtkPlugin {
  int (*read_dataset)(const char*, std::size_t, int, void*, char*, std::size_t) = nullptr;
  int (*write_dataset)(const void*, int, int, int, void*, char*, std::size_t) = nullptr;
};

// The plugin's entry points. Throws Status::io (exit 4) when the plugin or VTK itself
// cannot be loaded, naming the Debian package to install (formats/plugin_loader.hpp says
// where the plugin is looked for).
const VtkPlugin& vtk_plugin();

}  // namespace fest::formats::detail
