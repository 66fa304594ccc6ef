#pragma once
// Between fest's OpenMesh meshes and triangle soups (lib/core/triangle_soup.hpp): polygons
// are fan-triangulated from their first vertex, and the faces a reader could not put into
// OpenMesh (non-manifold ones) travel in the mesh properties that mesh_io.hpp provides for
// them, so nothing of a mesh is lost on the way in or out.

#include "core/mesh.hpp"
#include "core/triangle_soup.hpp"

namespace fest::formats {

// Vertices in the mesh's order with their normals, colours and texture coordinates where
// the mesh has them; the faces, then the skipped faces, as fans.
TriangleSoup to_triangle_soup(const Mesh& mesh);

// Faces OpenMesh rejects go into the extra-faces property, which the PLY/OFF/OBJ writers
// append, so non-manifold output is written exactly.
Mesh to_mesh(const TriangleSoup& soup);

}  // namespace fest::formats
