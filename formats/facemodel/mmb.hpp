#pragma once
// The morphable-model file of facefit, ".mmb" (man/man5/mmb.5):
//
//   bytes 0..7   magic "MORPHMB1"
//   bytes 8..15  u64 little endian H = length of the JSON header
//   bytes 16..   UTF-8 JSON header, space-padded so that every array starts 64-byte aligned
//   arrays       raw little-endian, at the offsets listed in the header
//
// The reader memory-maps the file read-only and points the model's basis into the map,
// so opening a 91 MB model costs page-table set-up, not a copy.

#include <string>

#include "core/face_model.hpp"

namespace fest::formats {

inline constexpr char mmb_magic[9] = "MORPHMB1";

struct MmbReadOptions {
  bool fix_basis = false;  // renormalise basis columns instead of rejecting them
};

// Opens and validates a model file (see check_model). Throws io_error when it cannot be
// opened, bad_input (message naming the file) when it is malformed or truncated.
// `warnings` receives messages such as "sigma reordered".
face::Model read_mmb(const std::string& path, const MmbReadOptions& options, std::string* warnings = nullptr);

// The same from bytes in memory (tests, fuzzing); the model owns a copy of the basis.
face::Model parse_mmb(std::string bytes, const MmbReadOptions& options, std::string* warnings = nullptr);

// Serialises a model (mean f64, basis as stored: f32 or f64, sigma f64, triangles u32,
// eval mask u32).
std::string write_mmb(const face::Model& model);

}  // namespace fest::formats
