// isosurf adaptive: the chapter's focus-adaptive crack-free surface from octree leaves of
// several levels (docs/isosurf.md section 5).
#include "commands.hpp"
#include "surface_pipeline.hpp"

namespace fest::isosurf_tool {

int run_adaptive(const ExactOptions& options, const AdaptiveArgs& adaptive) { return extract_surface(options, &adaptive); }

}  // namespace fest::isosurf_tool
