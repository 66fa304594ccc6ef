#pragma once
// Point rows as scanners and CGAL write them (.xyz, .pts, whitespace- or comma-separated
// "x y z [nx ny nz ...]"): bytes <-> points. Extra columns (normals) are ignored; one
// optional header line of names ("x,y,z") and lines starting with '#' are skipped.

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace fest::feshape {

// Throws Status::bad_input naming the line for a row with fewer than 3 numbers, a
// non-numeric field among the first three, or a non-finite coordinate.
std::vector<Eigen::Vector3d> decode_points(std::string_view text);

// "x y z\n" per point, shortest round-trip decimal form (decode_points reads it back exactly).
std::string encode_points(const std::vector<Eigen::Vector3d>& points);

}  // namespace fest::feshape
