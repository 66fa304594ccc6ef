#pragma once
// One input, read and recognised: the bytes (gunzipped if the file was gzip-compressed)
// and the format they are in.

#include <string>

#include "formats/detect.hpp"

namespace fest::formats {

struct Input {
  std::string name;   // the path as given, or "-" for standard input
  std::string bytes;  // decompressed content
  Format format;
  bool was_gzip = false;
};

// Reads a file or standard input ("-"), gunzips it when it starts with the gzip magic,
// and recognises its format. Throws fest::Error (io / bad_input), messages name `path`.
Input load_input(const std::string& path);

// The same for bytes already in memory (tests, fuzzers).
Input recognise(std::string bytes, const std::string& name = "-");

// Writes bytes to a path or standard output ("-"), gzip-compressing first when asked;
// atomically for files.
void store_output(const std::string& path, const std::string& bytes, bool gzip);

}  // namespace fest::formats
