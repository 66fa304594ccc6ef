#include "formats/input.hpp"

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/gzip.hpp"

namespace fest::formats {

Input recognise(std::string bytes, const std::string& name) {
  Input in;
  in.name = name;
  if (is_gzip(bytes)) {
    try {
      in.bytes = gunzip(bytes);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), name));
    }
    in.was_gzip = true;
  } else {
    in.bytes = std::move(bytes);
  }
  in.format = detect_format(in.bytes, name);
  return in;
}

Input load_input(const std::string& path) { return recognise(read_input(path), is_stdio(path) ? "-" : path); }

void store_output(const std::string& path, const std::string& bytes, bool compress) {
  if (compress)
    write_output(path, gzip(bytes));
  else
    write_output(path, bytes);
}

}  // namespace fest::formats
