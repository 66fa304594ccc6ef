#pragma once
// Meshes: PLY (ascii and binary), OBJ, OFF, STL (ascii and binary) and Draco .drc.

#include <string>
#include <string_view>

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

// Serialises a mesh. Coordinates written as text round-trip exactly.
std::string write_mesh(const Mesh& mesh, Format format, const MeshWriteOptions& options = {});

// Metadata for `fconv --info`: counts, bounding box, attributes present.
nlohmann::json describe_mesh(const Mesh& mesh);

}  // namespace fest::formats
