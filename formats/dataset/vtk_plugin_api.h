/* The interface of fest's VTK plugin (libfest_vtk_plugin.so), opened with dlopen by
 * formats/dataset on the first dataset read or written, so that tools map VTK's shared
 * libraries only when an input or output is a VTK dataset (a tool's start-up is paid
 * once per file in batch runs).
 *
 * The one entry point, fest_vtk_plugin_table, has C linkage, so dlsym finds it by a
 * plain name (formats/plugin_loader.hpp); the objects the table's functions
 * fill are fest's own C++ types (fest::Dataset, std::string), which is sound because the
 * plugin is built with fest, by the same compiler, from the same headers: the ABI number
 * below changes whenever core/dataset.hpp does, and the loader refuses a plugin that
 * reports another number or another layout of those types. */
#ifndef FEST_VTK_PLUGIN_API_H
#define FEST_VTK_PLUGIN_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FEST_VTK_PLUGIN_ABI 1

/* Every call returns 0, or fest's exit status for the failure (2 usage, 3 bad input,
 * 4 I/O) with a one-line message in `message`. `format` is a fest::formats::Format. */

/* bytes -> *(fest::Dataset*)dataset */
int fest_vtk_read_dataset(const char* bytes, size_t size, int format, void* dataset, char* message,
                          size_t message_size);
/* *(const fest::Dataset*)dataset -> *(std::string*)bytes */
int fest_vtk_write_dataset(const void* dataset, int format, int ascii, int zlib, void* bytes, char* message,
                           size_t message_size);
int fest_vtk_plugin_abi(void);
/* sizeof(fest::Dataset) * 65536 + sizeof(fest::DataArray) as the plugin was built: a
 * second guard, against a plugin and a tool built from different versions of
 * core/dataset.hpp under the same ABI number. */
size_t fest_vtk_plugin_layout(void);

typedef struct FestVtkPluginTable {
  int abi;       /* FEST_VTK_PLUGIN_ABI */
  size_t layout; /* fest_vtk_plugin_layout() */
  int (*read_dataset)(const char*, size_t, int, void*, char*, size_t);
  int (*write_dataset)(const void*, int, int, int, void*, char*, size_t);
} FestVtkPluginTable;
const FestVtkPluginTable* fest_vtk_plugin_table(void);

#ifdef __cplusplus
}
#endif

#endif
