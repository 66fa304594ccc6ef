#pragma once
// One input, read and recognised: the bytes (gunzipped if the file was gzip-compressed)
// and the format they are in.

#include <string>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

struct Input {
  std::string name;   // the path as given, or "-" for standard input
  std::string bytes;  // decompressed content
  Format format;
  bool was_gzip = false;
  // A .hdr/.img pair (NIfTI or Analyze) keeps its voxels in a second file: load_input
  // reads it (gunzipped) beside the header. Absent for standard input.
  bool has_companion = false;
  std::string companion_name;
  std::string companion;
};

// Reads a file or standard input ("-"), gunzips it when it starts with the gzip magic,
// and recognises its format. Throws fest::Error (io / bad_input), messages name `path`.
// The header of a .hdr/.img pair brings its image file along (x.hdr -> x.img, also
// .IMG and .img.gz); naming the .img reads the pair through its .hdr.
Input load_input(const std::string& path);

// The same for bytes already in memory (tests, fuzzers).
Input recognise(std::string bytes, const std::string& name = "-");

// Runs a reader on an input, naming the input in any bad-input error it throws
// ("PLY header: ... (bunny.ply)"): parse(in, read_mesh). A reader that takes the whole
// Input (formats::read_volume, for .hdr/.img pairs) is given it.
template <typename Reader>
auto parse(const Input& in, Reader&& read) -> decltype(read(in.bytes, in.format)) {
  try {
    if constexpr (std::is_invocable_v<Reader, const Input&>)
      return std::forward<Reader>(read)(in);
    else
      return std::forward<Reader>(read)(in.bytes, in.format);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), in.name));
  }
}

// Writes bytes to a path or standard output ("-"), gzip-compressing first when asked;
// atomically for files.
void store_output(const std::string& path, const std::string& bytes, bool gzip);

}  // namespace fest::formats
