#pragma once
// Landmark files of facefit (facefit(1)):
//  * observations: TSV with a header line, columns `id u v [sigma]` or `vertex u v [sigma]`
//    (tabs or spaces; `#` starts a comment), or iBUG .pts (`version: 1`, `n_points: N`,
//    `{`, N lines `x y`, `}`; point k gets id "k"; coordinates shifted by −pts_origin);
//  * landmark-to-vertex maps: TSV `name vertex` (an optional header line) or the eos
//    TOML subset (`[landmark_mappings]` then `name = vertex  # comment`; other sections
//    are ignored). Vertex sets (set17.tsv ...) are maps.

#include <string>
#include <string_view>
#include <vector>

#include "core/face_model.hpp"

namespace fest::formats {

// Throws bad_input with "(source:line)" for malformed lines and non-finite numbers.
std::vector<face::LandmarkEntry> read_landmarks(std::string_view text, const std::string& source, double pts_origin = 1.0);

face::LandmarkMap read_landmark_map(std::string_view text, const std::string& source);
// The same map as vertex list in file order (for vertex sets).
std::vector<face::NamedVertex> read_vertex_set(std::string_view text, const std::string& source);

// `id u v` TSV (with sigma when any entry has one); numbers as %.9g.
std::string write_landmarks(const std::vector<face::LandmarkEntry>& entries);
// `name vertex` TSV with a header line.
std::string write_vertex_set(const std::vector<face::NamedVertex>& set);

}  // namespace fest::formats
