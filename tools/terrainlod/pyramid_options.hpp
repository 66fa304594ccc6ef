#pragma once
// The pyramid parameters checked with the flags' names in the messages (lib/terrainlod
// checks them again in its own terms, for callers other than this tool).

namespace fest::terrainlod_tool {

// --tile, --texels (0 = --tile), --error-fraction: usage errors naming the flag.
void check_tile_options(int tile, int texels, double error_fraction);
// --height-quantum, --leaf-error: usage errors naming the flag.
void check_quantum_options(double height_quantum, double leaf_error);

}  // namespace fest::terrainlod_tool
