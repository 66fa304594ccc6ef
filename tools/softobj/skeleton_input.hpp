#pragma once
// Reading a skeleton: the scene JSON, or a mesh (OBJ/OFF/PLY...) whose triangles become
// charges (docs/softobj.md §1).

#include <string>

#include "commands.hpp"
#include "softobj/skeleton.hpp"

namespace fest::softobj_tool {

softobj::Skeleton read_skeleton(const std::string& path, SkeletonFormat format);

}  // namespace fest::softobj_tool
