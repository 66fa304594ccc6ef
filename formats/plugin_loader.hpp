#pragma once
// fest's plugin modules: the format families whose libraries are heavy to map (GDAL's
// rasters, TIFF, OpenEXR, ...) are compiled into small shared modules that a tool opens
// with dlopen only when an input or output needs them, so that a tool's start-up (paid
// once per file in a Makefile over thousands of files) maps none of them otherwise.

namespace fest::formats {

struct PluginModule {
  const char* file;     // "libfest_tiff_plugin.so"
  const char* entry;    // the exported symbol to look up
  const char* what;     // "TIFF support": the start of the error message
  const char* package;  // the Debian package whose absence is the likely cause
};

// Opens the module (once per process and module) and returns the address of its entry
// symbol. Looks in $FEST_PLUGIN_DIR when set, else beside the executable (build tree),
// else in the installed plugin folder (FEST_PLUGIN_RELDIR, relative to the executable).
// Throws Status::io (exit 4) with one line naming the package when the module or the
// library it needs cannot be loaded; a later call tries again.
void* plugin_entry(const PluginModule& module);

// The table the module's entry function returns (every fest plugin exports one function
// `const Table* entry(void)`), with plugin_entry's loading and errors.
template <class Table>
const Table* plugin_table(const PluginModule& module) {
  using Entry = const Table* (*)();
  return reinterpret_cast<Entry>(plugin_entry(module))();
}

}  // namespace fest::formats
