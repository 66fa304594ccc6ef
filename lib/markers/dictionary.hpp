#pragma once
// Square binary-code dictionaries (ArUco, AprilTag): n x n data cells inside a one-cell
// black border (docs/markerpose.md §3 "Identification"). Codes are n*n-bit words, cell
// (r, c) at bit n*n-1-(r*n+c), 1 = white. Decoding tries the four rotations and accepts
// the nearest code within the dictionary's correction radius.

#include <cstdint>
#include <string>
#include <vector>

namespace fest::markers {

struct Dictionary {
  std::string name;  // "4x4_50", "apriltag_36h11", ...
  int bits = 0;      // n
  std::vector<std::uint64_t> codes;
  int min_distance = 0;    // smallest Hamming distance between any two codes in any rotation
                           // (and between a code and its own rotations)
  int max_correction = 0;  // bit errors accepted: floor(0.6 (min_distance - 1) / 2), ArUco's rate
};

// Names: NxN_COUNT with N in 4..7 and COUNT in 50, 100, 250, 1000 (the ArUco tables;
// smaller dictionaries are prefixes of the 1000-code table), aruco_original,
// apriltag_16h5, apriltag_25h9, apriltag_36h10, apriltag_36h11. Throws fest::Error
// (bad_input) naming the known dictionaries for any other name. Cached: cheap to call.
const Dictionary& dictionary(const std::string& name);
std::vector<std::string> dictionary_names();

// 90-degree counter-clockwise rotation of an n x n code: new(r, c) = old(c, n-1-r).
std::uint64_t rotate_code_ccw(std::uint64_t code, int n);

struct Decoded {
  int id = -1;         // -1: no code within the correction radius
  int rotation = 0;    // k: the sampled grid rotated ccw k times equals the code
  int bit_errors = 0;
  int erasures = 0;
};

// `uncertain` marks cells read too close to the threshold: they are erasures, left out of
// the comparison. Accepted when errors <= max_correction and 2 errors + erasures <
// min_distance (the errors-and-erasures bound of a code of that distance).
Decoded decode(const Dictionary& dict, std::uint64_t sampled, std::uint64_t uncertain = 0);

}  // namespace fest::markers
