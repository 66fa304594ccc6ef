#pragma once
// Meshes: PLY (ascii and binary), OBJ, OFF, STL (ascii and binary) and Draco .drc.
//
// What each format keeps (read and write):
//  * PLY: positions (float or double), vertex normals, vertex colours, vertex texture
//    coordinates (s/t, u/v, texture_u/texture_v), face colours; reads ascii, binary
//    little and big endian; writes ascii or binary little endian. Binary output stores
//    positions (and normals) as `float` only when every value is exactly a float,
//    `double` otherwise, so nothing is rounded silently.
//  * OFF: [ST][C][N]OFF headers (COFF, NOFF, CNOFF, STOFF ...), face colours; colours
//    are written as integers 0..255 with alpha 255. Binary OFF and 4OFF/nOFF are not
//    supported (bad_input).
//  * OBJ: v (with the optional "r g b" colour extension), vt, vn, f (all index forms,
//    negative = relative). OBJ attaches normals and texture coordinates to face corners;
//    the first corner that names a vertex gives that vertex its normal/texcoord. Face
//    colours are not kept (OBJ needs a material library for them).
//  * STL: triangles only (polygons are written as fans); vertices with exactly equal
//    coordinates are merged on reading (STL stores each triangle on its own), in order
//    of first appearance; facet normals are kept as face normals. Binary STL stores
//    floats, so binary STL output rounds coordinates that are not floats: use ascii STL
//    (exact, shortest round-trip text) or another format to keep doubles.
//  * Draco: positions, normals, colours, texture coordinates; triangles only. Lossless
//    (draco_position_bits = 0) uses Draco's sequential coding, which keeps vertex and
//    face order and stores positions as float64 when they are not all floats; quantized
//    output may reorder vertices and faces (edgebreaker) and moves each position by at
//    most half a quantization step (bbox extent / (2^bits - 1) / 2).
// Text output writes every coordinate in shortest round-trip form, so text round trips
// are bit-exact. Readers keep vertex and face order.
//
// Faces that OpenMesh's halfedge structure cannot hold (fewer than three vertices, a
// vertex repeated, a complex edge, a non-manifold vertex -- raw scans have them) do not
// make reading fail and do not vanish silently: they are skipped and counted in the
// mesh property `skipped_faces_property` ("fest:skipped_faces", a std::size_t), which
// skipped_faces() reads and describe_mesh reports as "skipped_faces". A vertex index
// outside the vertex list, by contrast, is malformed data: bad_input.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/mesh.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

struct MeshWriteOptions {
  bool ascii = false;         // PLY and STL: ascii instead of binary (OBJ/OFF are always text)
  int draco_position_bits = 0;  // Draco quantization of positions; 0 = lossless
  int draco_speed = 5;          // Draco encoder speed 0 (best) .. 10 (fastest)
};

// Parses bytes already recognised as `format` (one of the mesh formats). Throws
// fest::Error(Status::bad_input) for anything malformed, without crashing or
// allocating more than the input can justify.
Mesh read_mesh(std::string_view bytes, Format format);

// Serialises a mesh. Coordinates written as text round-trip exactly. Throws
// Status::usage for options out of range (draco_position_bits 0..30, draco_speed
// 0..10) and Status::bad_input for a non-mesh format.
std::string write_mesh(const Mesh& mesh, Format format, const MeshWriteOptions& options = {});

// Metadata for `fconv --info`: counts, bounding box, attributes present.
// Keys: "vertices", "faces", "edges", "triangles" (all faces are triangles), "bbox"
// ({"min":[x,y,z],"max":[x,y,z]}, null for a mesh without vertices), "attributes"
// (from "vertex_normals", "vertex_colors", "vertex_texcoords", "face_colors",
// "face_normals") and "skipped_faces" when a reader skipped any.
nlohmann::json describe_mesh(const Mesh& mesh);

// Name of the mesh property (std::size_t) holding the number of faces a reader skipped.
inline constexpr const char* skipped_faces_property = "fest:skipped_faces";
// That number, 0 when the property is absent.
std::size_t skipped_faces(const Mesh& mesh);

// The skipped faces themselves (vertex indices as in the file, in file order), for tools
// that keep non-manifold input exactly (ebcode). Mesh property
// "fest:skipped_face_list" (std::vector<std::vector<int>>); empty when absent.
inline constexpr const char* skipped_face_list_property = "fest:skipped_face_list";
std::vector<std::vector<int>> skipped_face_list(const Mesh& mesh);

// Faces the writers of PLY, OFF and OBJ append after the mesh's own faces: the way to
// write faces OpenMesh's halfedge structure cannot hold (non-manifold output, ebdecode).
// Mesh property "fest:extra_faces" (std::vector<std::vector<int>>, vertex indices).
inline constexpr const char* extra_faces_property = "fest:extra_faces";
void set_extra_faces(Mesh& mesh, std::vector<std::vector<int>> faces);
std::vector<std::vector<int>> extra_faces(const Mesh& mesh);

}  // namespace fest::formats
