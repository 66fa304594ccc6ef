#include "formats/input.hpp"

#include <fstream>
#include <string>

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

namespace {

bool ends_with(const std::string& s, const char* suffix) {
  const std::size_t n = std::char_traits<char>::length(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

// x.img -> x.hdr and back (keeping the case of the extension and a .gz suffix);
// empty when the name has neither extension.
std::string sibling(const std::string& path, const char* from_lower, const char* to_lower, const char* from_upper,
                    const char* to_upper) {
  std::string base = path, gz;
  if (ends_with(base, ".gz") || ends_with(base, ".GZ")) {
    gz = base.substr(base.size() - 3);
    base.resize(base.size() - 3);
  }
  if (ends_with(base, from_lower)) return base.substr(0, base.size() - 4) + to_lower + gz;
  if (ends_with(base, from_upper)) return base.substr(0, base.size() - 4) + to_upper + gz;
  return {};
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

// The file itself, or the same name with ".gz" added or removed, whichever exists;
// empty when neither does.
std::string existing_variant(const std::string& path) {
  if (exists(path)) return path;
  const bool gz = ends_with(path, ".gz") || ends_with(path, ".GZ");
  const std::string alt = gz ? path.substr(0, path.size() - 3) : path + ".gz";
  return exists(alt) ? alt : std::string();
}

}  // namespace

Input load_input(const std::string& path) {
  if (is_stdio(path)) return recognise(read_input(path), "-");
  // Named by its image file: read the pair through its header.
  std::string header_path = path;
  if (const std::string hdr = sibling(path, ".img", ".hdr", ".IMG", ".HDR"); !hdr.empty())
    if (const std::string found = existing_variant(hdr); !found.empty()) header_path = found;
  Input in = recognise(read_input(header_path), header_path);
  if (in.format != Format::nifti_pair && in.format != Format::analyze) return in;
  // SPM keeps the orientation of an Analyze image in x.mat beside it (a MATLAB file
  // fest does not read); reading without it would place the voxels wrongly.
  if (in.format == Format::analyze) {
    std::string mat = sibling(header_path, ".hdr", ".mat", ".HDR", ".MAT");
    if (!mat.empty() && (ends_with(mat, ".gz") || ends_with(mat, ".GZ"))) mat.resize(mat.size() - 3);
    if (!mat.empty() && exists(mat))
      throw bad_input("{}", with_location(fmt::format("an SPM orientation file {} lies beside this Analyze 7.5 image, "
                                                      "and fest does not read it; convert the image to NIfTI with SPM "
                                                      "or nibabel first",
                                                      mat),
                                          header_path));
  }
  // The image file: x.img beside x.hdr (also compressed, or in the other case).
  std::string image = sibling(header_path, ".hdr", ".img", ".HDR", ".IMG");
  if (image.empty())
    throw bad_input("{}", with_location("this .hdr/.img pair header has a name without the .hdr extension, so "
                                        "its image file cannot be found",
                                        header_path));
  if (const std::string found = existing_variant(image); !found.empty()) image = found;
  else
    throw Error(Status::io, with_location(fmt::format("the image file {} of this .hdr/.img pair is missing", image), header_path));
  std::string bytes = read_input(image);
  if (is_gzip(bytes)) {
    try {
      bytes = gunzip(bytes);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), image));
    }
  }
  in.companion = std::move(bytes);
  in.companion_name = image;
  in.has_companion = true;
  return in;
}

void store_output(const std::string& path, const std::string& bytes, bool compress) {
  if (compress)
    write_output(path, gzip(bytes));
  else
    write_output(path, bytes);
}

}  // namespace fest::formats
