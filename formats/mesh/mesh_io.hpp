#pragma once
// Meshes: PLY (ascii and binary), OBJ, OFF, STL (ascii and binary) and Draco .drc.
//
// What each format keeps (read and write):
//  * PLY: positions (float or double), vertex normals, vertex colours, vertex texture
//    coordinates (s/t, u/v, texture_u/texture_v), face colours, the `edge` element
//    (vertex1 vertex2: line elements); reads ascii, binary little and big endian;
//    writes ascii or binary little endian. A header line that is not a PLY keyword
//    (Blender 2.47 writes "Created by Blender3D ..." without `comment`) is read as a
//    comment, with a read warning. Positions (and normals) are declared `float` unless
//    float32 would lose precision the input had (see CoordinatePrecision), then
//    `double`.
//  * OFF: [ST][C][N]OFF headers (COFF, NOFF, CNOFF, STOFF ...), face colours; colours
//    are written as integers 0..255 with alpha 255. Binary OFF and 4OFF/nOFF are not
//    supported (bad_input).
//  * OBJ: v (with the optional "r g b" colour extension), vt, vn, f (all index forms,
//    negative = relative), l (polylines) and p (points). OBJ attaches normals and
//    texture coordinates to face corners; the first corner that names a vertex gives
//    that vertex its normal/texcoord, and later corners naming other values are counted
//    in unread_parts() (with no corner naming normals and one vn per v -- MeshLab's
//    point clouds -- vn i is vertex i's). Face colours are not kept (OBJ needs a
//    material library for them).
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
// vertex repeated, a complex edge, a non-manifold vertex -- raw scans and assimp's test
// models have them) do not make reading fail and do not vanish: they are kept beside
// the halfedge mesh, in file order with their place among the file's faces (and their
// colour), and counted in the mesh property `skipped_faces_property`
// ("fest:skipped_faces", a std::size_t), which skipped_faces() reads and describe_mesh
// reports as "skipped_faces". carry_skipped_faces() makes the writers write them back
// in their place (fconv does; a tool that edits the halfedge mesh must not). A vertex
// index outside the vertex list, by contrast, is malformed data: bad_input.
//
// Line and point elements (OBJ l and p, the PLY edge element) are kept as lists of
// vertex indices beside the mesh (line_elements(), point_elements()); the OBJ writer
// writes both, the PLY writer writes lines as edges (a polyline of n vertices as n - 1
// edges). A format that cannot hold what a mesh carries (lines or points in OFF, STL or
// Draco; points in PLY; faces of fewer than three vertices in STL or Draco) makes
// write_mesh fail with bad_input naming what and how many, unless the write options
// allow dropping (unwritable_parts() lists it first, for the caller's warning).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/mesh.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"

namespace fest::formats {

// How binary PLY stores positions and normals. `automatic`: float32 unless float32 would
// lose precision the input had, judged by how the input stored them (the reader records
// it): a binary float input is float; a binary double (or 32-bit integer) input is
// double when any value is not exactly a float; decimal text (OBJ, OFF, ascii PLY/STL)
// is float when every value's text reads back from its float32 (up to 7 significant
// digits always do: 0.1 is a float to a text file), else double. The values are always
// checked, so coordinates a tool computed after reading stay double. A mesh no reader
// made is float when every value is exactly a float. `float32`/`float64` force the
// type (float32 then rounds to nearest).
enum class CoordinatePrecision { automatic, float32, float64 };

struct MeshWriteOptions {
  bool ascii = false;         // PLY and STL: ascii instead of binary (OBJ/OFF are always text)
  int draco_position_bits = 0;  // Draco quantization of positions; 0 = lossless (everything)
  // With positions quantized, normals and texture coordinates are quantized too, as
  // draco_encoder does (its -qn 8 and -qt 10 by default); 0 leaves that attribute unquantized.
  int draco_normal_bits = 8;
  int draco_texcoord_bits = 10;
  // Draco encoder speed 0 (best) .. 10 (fastest); draco_encoder's compression level -cl
  // is 10 - speed, and its default -cl 7 is speed 3.
  int draco_speed = 3;
  CoordinatePrecision precision = CoordinatePrecision::automatic;  // PLY positions and normals
  // Write without what the format cannot hold (see unwritable_parts) instead of failing.
  bool drop_unrepresentable = false;
};

// Something a mesh carries that a format cannot hold: "3 line elements (9 segments)".
struct MeshPart {
  std::string what;  // e.g. "line elements", "point elements", "faces of fewer than 3 vertices"
  std::size_t count = 0;
  std::string describe() const;  // "<count> <what>"
};
// What write_mesh(mesh, format) would have to drop; empty when the format holds it all.
std::vector<MeshPart> unwritable_parts(const Mesh& mesh, Format format);

// Parses bytes already recognised as `format` (one of the mesh formats). Throws
// fest::Error(Status::bad_input) for anything malformed, without crashing or
// allocating more than the input can justify.
//
// read_mesh(bytes, format) reads the bytes alone; read_mesh(input) also finds the files
// a scene refers to (a glTF's external .bin buffers) beside the input's path -- none for
// standard input, where such a scene fails with bad_input naming the file. It is one
// callable object so that `parse(in, read_mesh)` picks the Input form (as read_volume).
struct MeshReader {
  Mesh operator()(std::string_view bytes, Format format) const;
  Mesh operator()(const Input& in) const;
};
inline constexpr MeshReader read_mesh{};

// Serialises a mesh. Coordinates written as text round-trip exactly. Throws
// Status::usage for options out of range (draco_position_bits 0..30, draco_speed
// 0..10) and Status::bad_input for a non-mesh format.
std::string write_mesh(const Mesh& mesh, Format format, const MeshWriteOptions& options = {});

// Metadata for `fconv --info`: counts, bounding box, attributes present.
// Keys: "vertices", "faces", "edges", "triangles" (all faces are triangles), "bbox"
// ({"min":[x,y,z],"max":[x,y,z]}, null for a mesh without vertices), "attributes"
// (from "vertex_normals", "vertex_colors", "vertex_texcoords", "face_colors",
// "face_normals"), "skipped_faces" when a reader kept faces beside the halfedge mesh
// ("faces" counts them too), "lines" / "line_segments" / "points" when the mesh has
// line or point elements, "not_kept" (unread_parts(), as text) when a reader did not
// keep something.
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

// Faces every writer writes besides the mesh's own faces: the way to write faces
// OpenMesh's halfedge structure cannot hold (non-manifold output, ebdecode). Mesh
// property "fest:extra_faces" (std::vector<std::vector<int>>, vertex indices); they go
// after the mesh's own faces, or at the places carry_skipped_faces() recorded. STL and
// Draco write them as fans, like any polygon.
inline constexpr const char* extra_faces_property = "fest:extra_faces";
void set_extra_faces(Mesh& mesh, std::vector<std::vector<int>> faces);
std::vector<std::vector<int>> extra_faces(const Mesh& mesh);

// Makes the writers write the faces the reader kept beside the halfedge mesh, each at
// its place in the file's face order and with its colour, so that a conversion keeps
// every face in order. For a mesh as read (vertices and faces unchanged).
void carry_skipped_faces(Mesh& mesh);

// Every face the mesh holds: its own faces plus the skipped ones (as read) or the extra
// ones -- what fcompare compares.
std::size_t total_faces(const Mesh& mesh);
// The faces held beside the halfedge mesh: extra faces when set, else skipped ones.
std::vector<std::vector<int>> faces_beside(const Mesh& mesh);

// Line elements (polylines; OBJ l, PLY edge = 2 vertices) and point elements (OBJ p),
// vertex indices, in file order. Mesh properties "fest:line_elements" and
// "fest:point_elements" (std::vector<std::vector<int>>).
inline constexpr const char* line_elements_property = "fest:line_elements";
inline constexpr const char* point_elements_property = "fest:point_elements";
std::vector<std::vector<int>> line_elements(const Mesh& mesh);
std::vector<std::vector<int>> point_elements(const Mesh& mesh);
void set_line_elements(Mesh& mesh, std::vector<std::vector<int>> lines);
void set_point_elements(Mesh& mesh, std::vector<std::vector<int>> points);
std::size_t line_segments(const Mesh& mesh);  // sum over lines of (vertices - 1)
std::size_t point_count(const Mesh& mesh);     // sum over point elements of their vertices

// What the file holds that the reader read but fest's mesh does not keep: PLY
// properties other than the known ones ("1889 vertices' confidence, intensity (PLY
// properties)"), PLY elements other than vertex, face and edge, and OBJ face corners
// whose normal or texture coordinates differ from their vertex's (hard edges, seams:
// fest keeps one per vertex). Empty for OFF, STL and Draco. A converter must refuse or report them (fconv does, like unwritable_parts).
std::vector<MeshPart> unread_parts(const Mesh& mesh);

// What a reader could read only leniently (a PLY header line without `comment`), one
// message each, for the tool to print as warnings. Mesh property "fest:read_warnings".
std::vector<std::string> read_warnings(const Mesh& mesh);

}  // namespace fest::formats
