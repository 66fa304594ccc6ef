// Reading and writing datasets through the VTK plugin (vtk_plugin_loader.hpp): the
// plugin parses with VTK's guarded readers and hands back a fest::Dataset.

#include "formats/dataset/dataset_io.hpp"

#include "core/error.hpp"
#include "formats/dataset/vtk_plugin_loader.hpp"

namespace fest::formats {
namespace {

bool is_dataset_format(Format format) {
  return format == Format::vtu || format == Format::vti || format == Format::vtp || format == Format::vts ||
         format == Format::vtk;
}

[[noreturn]] void rethrow(int status, const char* message) {
  throw Error(static_cast<Status>(status), message);
}

}  // namespace

Dataset read_dataset(std::string_view bytes, Format format) {
  if (!is_dataset_format(format)) throw usage_error("{} is not a VTK dataset format", format_name(format));
  const detail::VtkPlugin& plugin = detail::vtk_plugin();
  Dataset dataset;
  char message[1024] = "";
  if (int status = plugin.read_dataset(bytes.data(), bytes.size(), static_cast<int>(format), &dataset, message,
                                       sizeof message))
    rethrow(status, message);
  return dataset;
}

std::string write_dataset(const Dataset& dataset, Format format, const DatasetWriteOptions& options) {
  if (!is_dataset_format(format)) throw usage_error("{} is not a VTK dataset format", format_name(format));
  const detail::VtkPlugin& plugin = detail::vtk_plugin();
  std::string bytes;
  char message[1024] = "";
  if (int status = plugin.write_dataset(&dataset, static_cast<int>(format), options.ascii ? 1 : 0,
                                        options.zlib ? 1 : 0, &bytes, message, sizeof message))
    rethrow(status, message);
  return bytes;
}

}  // namespace fest::formats
