// The NumPy .npz model importer (formats/facemodel/npz_model.cpp: zip members through
// minizip, stored or deflated, then the .npy headers and arrays), followed by the
// invariant check every model passes before use. The reader takes a path, so the bytes
// go through a file of this process's own. Any bytes either give a checked model or
// throw fest::Error.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/face_model_basis.hpp"
#include "formats/facemodel/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/fuzz_npz_model." + std::to_string(::getpid()) + ".npz";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  const bool written = std::fwrite(data, 1, size, f) == size;
  std::fclose(f);
  if (!written) return 0;
  try {
    std::string warnings;
    fest::face::Model m = fest::formats::read_npz_model(path, &warnings);
    fest::face::check_model(m, true);
  } catch (const fest::Error&) {
  }
  return 0;
}
