#pragma once
// Landmark observations as read from a file, before they are tied to model vertices:
// each names a landmark id (looked up in a landmark-to-vertex map) or a vertex index.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/face_model.hpp"
#include "facefit/fit.hpp"

namespace fest::facefit {

// Entries and maps are plain data shared with formats/facemodel (core/face_model.hpp).
using face::LandmarkEntry;
using face::LandmarkMap;

// Ties entries to vertices through `map`. An id missing from the map is bad input
// (naming the id and `source:line`) unless skip_unmapped, then it is counted in *skipped.
Landmarks resolve_landmarks(const std::vector<LandmarkEntry>& entries, const LandmarkMap& map, bool skip_unmapped,
                            std::size_t* skipped, const std::string& source);

}  // namespace fest::facefit
