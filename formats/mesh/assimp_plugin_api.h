/* The interface of fest's assimp plugin (libfest_assimp_plugin.so), opened with dlopen by
 * formats/mesh on the first glTF, GLB, COLLADA, FBX, 3DS, DirectX .x or LightWave file
 * read, so that tools map libassimp (and the libraries it pulls in) only when such a file
 * arrives: a tool's start-up is paid once per file in batch runs.
 *
 * The one entry point, fest_assimp_plugin_table, has C linkage so that dlsym finds it by
 * a plain name (formats/plugin_loader.hpp). The scene it fills is
 * fest::formats::AssimpScene (assimp_scene.hpp: standard containers only), sound because
 * the plugin is built with fest by the same compiler from the same header; the ABI number
 * below changes whenever that header does, and the loader also compares the struct's size. */
#ifndef FEST_ASSIMP_PLUGIN_API_H
#define FEST_ASSIMP_PLUGIN_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FEST_ASSIMP_PLUGIN_ABI 2

typedef struct FestAssimpPluginTable {
  int abi;       /* FEST_ASSIMP_PLUGIN_ABI */
  size_t layout; /* sizeof(fest::formats::AssimpScene) as the plugin was built */
  /* bytes (extension hint "gltf", "3ds", ...) -> *(fest::formats::AssimpScene*)scene.
   * `folder`: where the files the scene refers to lie (a glTF's .bin buffers), the scene
   * file's folder; NULL when the scene has no file (standard input), and then such a
   * scene fails naming the file. Returns 0, or 3 (bad input) or 4 (a file the scene
   * refers to cannot be read) with a one-line message in `message`. */
  int (*read_scene)(const char* bytes, size_t size, const char* hint, const char* folder, void* scene,
                    char* message, size_t message_size);
} FestAssimpPluginTable;
const FestAssimpPluginTable* fest_assimp_plugin_table(void);

#ifdef __cplusplus
}
#endif

#endif
