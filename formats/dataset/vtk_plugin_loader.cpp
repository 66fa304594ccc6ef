#include "formats/dataset/vtk_plugin_loader.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "core/dataset.hpp"
#include "core/error.hpp"
#include "formats/dataset/vtk_plugin_api.h"

#ifndef FEST_PLUGIN_RELDIR
#define FEST_PLUGIN_RELDIR "../lib/fest"
#endif

namespace fest::formats::detail {
namespace {

constexpr const char* kPluginFile = "libfest_vtk_plugin.so";
// Debian 12's VTK runtime (libvtk9.1 holds libvtkCommonCore-9.1.so.1 and the IO
// modules); a missing plugin almost always means a missing libvtk (the plugin itself
// ships with fest).
constexpr const char* kVtkPackage = "libvtk9.1";

std::string executable_dir() {
  std::vector<char> buf(4096);
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return ".";
  std::string path(buf.data(), std::size_t(n));
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::vector<std::string> candidates() {
  if (const char* dir = std::getenv("FEST_PLUGIN_DIR"); dir && *dir) return {std::string(dir) + "/" + kPluginFile};
  const std::string exe = executable_dir();
  return {exe + "/" + kPluginFile, exe + "/" FEST_PLUGIN_RELDIR "/" + kPluginFile};
}

VtkPlugin load() {
  std::string why;
  for (const std::string& path : candidates()) {
    if (::access(path.c_str(), F_OK) != 0) continue;
    // Lazy binding, as the executable itself gets: resolving all of VTK's symbols up
    // front (RTLD_NOW) cost 25 million instructions for one small .vtu (callgrind), more
    // than the conversion. A VTK library that is missing still fails here.
    void* handle = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
      const char* e = ::dlerror();
      why = e ? e : "dlopen failed";
      break;  // found but unloadable: most likely libvtk itself is missing
    }
    auto abi = reinterpret_cast<int (*)()>(::dlsym(handle, "fest_vtk_plugin_abi"));
    auto layout = reinterpret_cast<std::size_t (*)()>(::dlsym(handle, "fest_vtk_plugin_layout"));
    VtkPlugin p;
    p.read_dataset = reinterpret_cast<decltype(p.read_dataset)>(::dlsym(handle, "fest_vtk_read_dataset"));
    p.write_dataset = reinterpret_cast<decltype(p.write_dataset)>(::dlsym(handle, "fest_vtk_write_dataset"));
    if (!abi || abi() != FEST_VTK_PLUGIN_ABI || !layout ||
        layout() != sizeof(Dataset) * 65536 + sizeof(DataArray) || !p.read_dataset || !p.write_dataset) {
      why = path + " is from another fest version";
      break;
    }
    return p;
  }
  if (why.empty()) why = std::string(kPluginFile) + " not found beside the executable or in " FEST_PLUGIN_RELDIR;
  throw io_error("VTK dataset support is not available ({}); install the Debian package {} (and fest's {})", why,
                 kVtkPackage, kPluginFile);
}

}  // namespace

const VtkPlugin& vtk_plugin() {
  static std::mutex m;
  static VtkPlugin plugin;
  static bool loaded = false;
  std::lock_guard<std::mutex> lock(m);
  if (!loaded) {
    plugin = load();  // throws, leaving `loaded` false so a later call reports again
    loaded = true;
  }
  return plugin;
}

}  // namespace fest::formats::detail
