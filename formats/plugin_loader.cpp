#include "formats/plugin_loader.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"

#ifndef FEST_PLUGIN_RELDIR
#define FEST_PLUGIN_RELDIR "../lib/fest"
#endif

namespace fest::formats {
namespace {

std::string executable_dir() {
  std::vector<char> buf(4096);
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return ".";
  std::string path(buf.data(), std::size_t(n));
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::vector<std::string> candidates(const char* file) {
  if (const char* dir = std::getenv("FEST_PLUGIN_DIR"); dir && *dir) return {std::string(dir) + "/" + file};
  const std::string exe = executable_dir();
  return {exe + "/" + file, exe + "/" FEST_PLUGIN_RELDIR "/" + file};
}

void* open_entry(const PluginModule& module) {
  std::string why;
  for (const std::string& path : candidates(module.file)) {
    if (::access(path.c_str(), F_OK) != 0) continue;
    // RTLD_LOCAL: the module's libraries stay out of the global namespace, so two
    // modules cannot interpose each other's symbols. Lazy binding, as the executable
    // itself gets: resolving all of VTK's symbols up front (RTLD_NOW) cost 25 million
    // instructions for one small .vtu (callgrind), more than the conversion; a library
    // that is missing still fails here.
    void* handle = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
      const char* e = ::dlerror();
      why = e ? e : "dlopen failed";
      break;  // found but unloadable: most likely the library it wraps is missing
    }
    if (void* entry = ::dlsym(handle, module.entry)) return entry;
    why = path + " is from another fest version";
    break;
  }
  if (why.empty()) why = std::string(module.file) + " not found beside the executable or in " FEST_PLUGIN_RELDIR;
  throw io_error("{} is not available ({}); install the Debian package {} (and fest's {})", module.what, why,
                 module.package, module.file);
}

}  // namespace

void* plugin_entry(const PluginModule& module) {
  static std::mutex m;
  static std::map<std::string, void*> loaded;
  std::lock_guard<std::mutex> lock(m);
  if (auto it = loaded.find(module.entry); it != loaded.end()) return it->second;
  void* entry = open_entry(module);  // throws, leaving nothing cached
  loaded.emplace(module.entry, entry);
  return entry;
}

}  // namespace fest::formats
