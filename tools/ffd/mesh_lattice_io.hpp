#pragma once
// What ffd's commands read and write beside the lattice maths (fest_ffd_app): lattice
// files (JSON or PyGeM .prm), meshes and their points, output formats and the names of
// per-object and per-frame outputs, the fixed control points.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mesh.hpp"
#include "commands.hpp"
#include "ffd/lattice.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::ffd_tool {

using ffd::Lattice;

// A lattice file: JSON when it starts with '{', else PyGeM .prm (docs/ffd.md 4).
Lattice load_lattice(const std::string& path);
// A mesh file (any mesh format fest reads); its format in *format when asked.
Mesh load_mesh(const std::string& path, formats::Format* format = nullptr);
// The mesh format to write: --to, else the output's extension, else the input's.
formats::OutputFormat output_format(const std::string& to, const std::string& path, formats::Format input);
// Lattices beyond 64^3 control points only when allowed.
void check_size(const Lattice& l, bool allow_large);
// The mesh's vertex positions, and back.
std::vector<Eigen::Vector3d> points_of(const Mesh& m);
void set_points(Mesh& m, const std::vector<Eigen::Vector3d>& p);
// A third of the incident face areas per vertex (the weights a_v of docs/ffd.md 2.4).
std::vector<double> vertex_areas(const Mesh& m);
// Vertex normals after a deformation: recomputed from the faces, or carried by the
// inverse transpose of the Jacobian (NormalsMode::jacobian).
void update_normals(Mesh& m, NormalsMode mode, const ffd::Deformer* d, const std::vector<Eigen::Vector3d>& rest,
                    ffd::Outside outside);
// Control points to keep in place: lines "i j k" (# comments), as lattice indices.
std::vector<std::size_t> read_fixed(const std::string& path, const Lattice& l);
// The output of one object: -o's %s replaced by its name when there are several.
std::string object_output(const std::string& pattern, const std::string& name, std::size_t objects);
// The pattern's one "%d" or "%0Nd" replaced by the frame number (no printf: the pattern
// is user text).
std::string frame_name(const std::string& pattern, long frame);

}  // namespace fest::ffd_tool
