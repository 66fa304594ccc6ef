#pragma once
// The files facefit's subcommands read and write: model loading (path or $FACEFIT_MODEL),
// shapes <-> meshes, mesh output, small text files.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "commands.hpp"
#include "core/mesh.hpp"
#include "facefit/landmark_set.hpp"
#include "facefit/model.hpp"

namespace fest::facefit_tool {

inline constexpr const char* tool = "facefit";

void warn(const std::string& message);

// -m FILE, else $FACEFIT_MODEL; usage error when neither is given.
std::string model_path(const std::string& option);
// Bad input naming --fix-basis where renormalising the basis would accept the model.
fest::facefit::Model load_model(const std::string& option, bool fix_basis = false);
// facefit::check_model, its refusal naming --fix-basis where that would accept the model.
fest::facefit::CheckResult check_model_naming_flags(fest::facefit::Model& m, bool fix_basis);

// A shape vector (interleaved xyz) with the model's triangles as a mesh.
fest::Mesh shape_to_mesh(const Eigen::VectorXd& shape, int dims, const std::vector<std::array<std::uint32_t, 3>>& triangles);
// Vertex positions of a mesh file as a shape vector (3 per vertex).
Eigen::VectorXd read_shape(const std::string& path, std::vector<std::array<std::uint32_t, 3>>* triangles = nullptr);
// Writes a mesh to a path or stdout; format from --to (parsed), else the extension, else binary PLY.
void write_mesh_to(const fest::Mesh& mesh, const std::string& path, const std::optional<MeshOutput>& to);
// A shape with triangles: binary PLY (float32 coordinates) straight from the arrays when
// that is the output format, else through write_mesh_to (text formats keep doubles).
// Whether write_shape writes PATH (with --to TO) as binary PLY straight from the arrays.
bool writes_binary_ply(const std::string& path, const std::optional<MeshOutput>& to);
void write_shape(const Eigen::VectorXd& shape, int dims, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                 const std::string& path, const std::optional<MeshOutput>& to);

// Reads a whole text file ("-" = stdin).
std::string read_text(const std::string& path);
std::vector<std::string> read_list(const std::string& path);  // one path per line; relative to the list's folder
std::vector<std::uint32_t> read_vertex_indices(const std::string& path);  // a vertex set or mask file
fest::facefit::LandmarkMap read_map(const std::string& path);

}  // namespace fest::facefit_tool
