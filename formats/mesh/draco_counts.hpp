#pragma once
// A look at a Draco file's element counts before libdraco decodes it.
//
// libdraco 1.5 reserves memory from the counts a file claims (its edgebreaker decoder
// reserved 3.3 GB for a 95-byte file found by fuzzing). This reads the same header
// fields the decoder will read and refuses counts the input cannot plausibly encode.

#include <string_view>

namespace fest::formats::mesh_detail {

// Throws Status::bad_input for a header Draco would misread or over-allocate on, and for
// bitstream versions Draco 1.4 and later do not write (2.2 meshes, 2.3 point clouds).
void check_draco_counts(std::string_view bytes);

}  // namespace fest::formats::mesh_detail
