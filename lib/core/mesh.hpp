#pragma once
// The mesh type of fest: an OpenMesh polygon mesh with double-precision points.
// Double points keep coordinates from double-precision files exact; readers of float
// formats convert exactly (every float is a double). Normals, colours and texture
// coordinates are requested per mesh (request_vertex_normals() ...) when a file has them.

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace fest {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  using Color = OpenMesh::Vec3uc;
  using TexCoord2D = OpenMesh::Vec2f;
};

using Mesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

}  // namespace fest
