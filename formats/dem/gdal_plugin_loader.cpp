#include "formats/dem/gdal_plugin_loader.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"

#ifndef FEST_PLUGIN_RELDIR
#define FEST_PLUGIN_RELDIR "../lib/fest"
#endif

namespace fest::formats::dem_detail {
namespace {

constexpr const char* kPluginFile = "libfest_gdal_plugin.so";
// Debian 12's GDAL runtime; the message names it because a missing plugin almost always
// means a missing libgdal (the plugin itself ships with fest).
constexpr const char* kGdalPackage = "libgdal32";

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

GdalPlugin load() {
  std::string why;
  for (const std::string& path : candidates()) {
    if (::access(path.c_str(), F_OK) != 0) continue;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* e = ::dlerror();
      why = e ? e : "dlopen failed";
      break;  // found but unloadable: most likely libgdal itself is missing
    }
    auto abi = reinterpret_cast<int (*)()>(::dlsym(handle, "fest_gdal_plugin_abi"));
    GdalPlugin p;
    p.open_raster = reinterpret_cast<decltype(p.open_raster)>(::dlsym(handle, "fest_gdal_open_raster"));
    p.free_raster = reinterpret_cast<decltype(p.free_raster)>(::dlsym(handle, "fest_gdal_free_raster"));
    if (!abi || abi() != FEST_GDAL_PLUGIN_ABI || !p.open_raster || !p.free_raster) {
      why = path + " is from another fest version";
      break;
    }
    return p;
  }
  if (why.empty()) why = std::string(kPluginFile) + " not found beside the executable or in " FEST_PLUGIN_RELDIR;
  throw io_error("GDAL raster support is not available ({}); install the Debian package {} (and fest's {})", why,
                 kGdalPackage, kPluginFile);
}

}  // namespace

const GdalPlugin& gdal_plugin() {
  static std::mutex m;
  static GdalPlugin plugin;
  static bool loaded = false;
  std::lock_guard<std::mutex> lock(m);
  if (!loaded) {
    plugin = load();  // throws, leaving `loaded` false so a later call reports again
    loaded = true;
  }
  return plugin;
}

}  // namespace fest::formats::dem_detail
