#include "volume_files.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/input.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::segbrain_tool {

Volume read_volume_input(const std::string& path, const char* what) {
  formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::volume)
    throw bad_input("expected a volume (NIfTI, NRRD, MHA), got {} ({})", formats::format_name(in.format), in.name);
  Volume v = formats::parse(in, formats::read_volume);
  v.require_3d(fmt::format("{} ({})", what, in.name).c_str());
  return v;
}

void write_volume_output(const Volume& v, const std::string& path, const std::optional<formats::OutputFormat>& to) {
  formats::OutputFormat of{formats::Format::nifti, false};
  if (to) of = *to;
  else if (!is_stdio(path)) of = formats::output_format_from_path(path);
  if (formats::kind_of(of.format) != formats::Kind::volume) throw usage_error("--to: not a volume format");
  formats::store_volume(path, v, of);
}

}  // namespace fest::segbrain_tool
