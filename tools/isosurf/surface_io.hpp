#pragma once
// isosurf's surfaces <-> mesh files (formats/mesh), and the stats report as JSON.

#include <string>

#include <nlohmann/json.hpp>

#include "isosurface/mesh_stats.hpp"
#include "isosurface/surface.hpp"

namespace fest::isosurf_tool {

// Bytes of the surface in a mesh format named like --to (ply, plya, obj, off, stl, drc).
// Binary PLY without normals is written straight from the arrays; the rest goes through the
// project's mesh type, with faces its halfedge structure refuses carried as extra faces.
std::string encode_surface(const isosurface::Surface& s, const std::string& format, int draco_bits);

// Any mesh file -> surface: polygons are fanned into triangles (counted in `fanned`),
// faces the reader could not hold in its halfedge structure are included.
isosurface::Surface decode_surface(const std::string& bytes_name, std::size_t& fanned);

nlohmann::json stats_json(const isosurface::MeshStats& m);

// The output format: --to, else the extension of -o, else ply.
std::string output_format(const std::string& to, const std::string& output);

}  // namespace fest::isosurf_tool
