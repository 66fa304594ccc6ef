// The eos / cereal binary model importer (formats/facemodel/eos_model.cpp, facefit convert
// --from eos), followed by the invariant check every model passes before use
// (core/face_model_basis.hpp): any bytes either give a checked model or throw fest::Error.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/face_model_basis.hpp"
#include "formats/facemodel/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    fest::face::Model m = fest::formats::read_eos_model(bytes, "fuzz");
    fest::face::check_model(m, true);
  } catch (const fest::Error&) {
  }
  return 0;
}
