// isosurf exact: full-resolution loop-construction marching cubes over the min-max
// pyramid (docs/isosurf.md sections 2-3).
#include "commands.hpp"
#include "surface_pipeline.hpp"

namespace fest::isosurf_tool {

int run_exact(const ExactOptions& options) { return extract_surface(options, nullptr); }

}  // namespace fest::isosurf_tool
