#pragma once
// Landmark observations as read from a file, before they are tied to model vertices:
// each names a landmark id (looked up in a landmark-to-vertex map) or a vertex index.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "facefit/fit.hpp"

namespace fest::facefit {

struct LandmarkEntry {
  std::string id;             // landmark name ("37", "nose_tip"); empty when given by vertex
  bool by_vertex = false;
  std::uint32_t vertex = 0;
  double u = 0, v = 0;        // px
  double sigma = 0;           // px, 0 = not given
  std::size_t line = 0;       // source line, for messages
};

using LandmarkMap = std::map<std::string, std::uint32_t>;

// Ties entries to vertices through `map`. An id missing from the map is bad input
// (naming the id and `source:line`) unless skip_unmapped, then it is counted in *skipped.
Landmarks resolve_landmarks(const std::vector<LandmarkEntry>& entries, const LandmarkMap& map, bool skip_unmapped,
                            std::size_t* skipped, const std::string& source);

}  // namespace fest::facefit
