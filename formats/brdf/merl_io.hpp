#pragma once
// The MERL BRDF database's .binary layout (Matusik et al. 2003): three int32 (little
// endian) dimensions 90, 90, 180, then 3 x 90 x 90 x 180 doubles (R plane, G, B), raw
// (the reader of the values applies the channel scales 1/1500, 1.15/1500, 1.66/1500).

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats {

struct MerlFile {
  std::array<int, 3> dims = {90, 90, 180};
  std::vector<double> values;  // 3 x dims product, plane by plane
};

// Throws bad_input (with the offset) for other dimensions or a size that does not match.
MerlFile read_merl(std::string_view bytes);
std::string write_merl(const MerlFile& file);

}  // namespace fest::formats
