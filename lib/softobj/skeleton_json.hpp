#pragma once
// The skeleton scene JSON (softobj(1)) as a codec, text <-> Skeleton:
//   {"vertices": [[x,y,z],...], "triangles": [[i,j,k],...], "segments": [[i,j],...],
//    "points": [i,...], "charge": 1.0 | [per primitive...], "iso": 0.1667, "units": "mm"}

#include <string>
#include <string_view>

#include "softobj/skeleton.hpp"

namespace fest::softobj {

// Throws fest::Error(bad_input) for malformed JSON, wrong shapes, non-finite numbers and
// out-of-range indices, naming the member.
Skeleton decode_skeleton(std::string_view text);
std::string encode_skeleton(const Skeleton& s);

}  // namespace fest::softobj
