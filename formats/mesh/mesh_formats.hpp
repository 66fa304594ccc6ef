#pragma once
// Private to formats/mesh: one reader and one writer per file format. mesh_io.cpp
// dispatches on the Format and these do the work.
//
// Why fest has its own PLY/OBJ/OFF/STL readers and writers instead of OpenMesh::IO:
// OpenMesh 9's readers parse every coordinate into a float (Vec3f), even into a
// double-point mesh ("0.123456789012345" comes back as 0.12345679104328156), which
// breaks the project's exactness requirement; they also reserve memory from header
// counts before checking them, print to omerr, and silently drop faces that
// add_face rejects. These readers keep coordinates bit-exact, preserve vertex and
// face order, check every count against the bytes available before allocating, and
// count the faces OpenMesh's connectivity cannot hold (see mesh_builder.hpp).
// Draco goes through the Draco library (draco_format.cpp).

#include <string>
#include <optional>
#include <string_view>

#include "core/mesh.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::formats::mesh_detail {

Mesh read_ply(std::string_view bytes);
std::string write_ply(const Mesh& mesh, bool ascii, CoordinatePrecision precision);

Mesh read_off(std::string_view bytes);
std::string write_off(const Mesh& mesh);

Mesh read_obj(std::string_view bytes);
std::string write_obj(const Mesh& mesh);

Mesh read_stl(std::string_view bytes);
std::string write_stl(const Mesh& mesh, bool ascii);

Mesh read_drc(std::string_view bytes);

// glTF/GLB, COLLADA, FBX, 3DS, .x, LightWave through the assimp plugin (read only).
// `folder`: where the files the scene refers to lie (the scene file's folder); none
// for bytes without a file (standard input).
Mesh read_assimp(std::string_view bytes, Format format, const std::optional<std::string>& folder);
std::string write_drc(const Mesh& mesh, const MeshWriteOptions& options);

}  // namespace fest::formats::mesh_detail
