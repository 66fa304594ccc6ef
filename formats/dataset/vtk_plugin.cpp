// fest's VTK plugin: the only code of the tools' that calls VTK, built as a shared
// module that formats/dataset opens with dlopen on first use (vtk_plugin_api.h says
// why). Errors never cross the boundary as exceptions: each entry point turns them into
// fest's exit status and a one-line message.
#include "formats/dataset/vtk_plugin_api.h"

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include <vtkDataSet.h>

#include "core/error.hpp"
#include "formats/dataset/vtk_convert.hpp"
#include "formats/dataset/vtk_dataset_io.hpp"

namespace {

int fail(int status, char* message, size_t size, const char* text) {
  std::snprintf(message, size, "%s", text);
  for (char* c = message; *c; ++c)
    if (*c == '\n' || *c == '\r') *c = ' ';
  return status;
}

template <typename Work>
int guarded(char* message, size_t size, Work work) {
  try {
    work();
    return 0;
  } catch (const fest::Error& e) {
    return fail(static_cast<int>(e.status()), message, size, e.what());
  } catch (const std::bad_alloc&) {
    return fail(static_cast<int>(fest::Status::bad_input), message, size,
                "the dataset needs more memory than is available");
  } catch (const std::exception& e) {
    return fail(static_cast<int>(fest::Status::bad_input), message, size, e.what());
  }
}

const char* name_of(fest::formats::Format f) {
  using fest::formats::Format;
  switch (f) {
    case Format::vtu: return "vtu";
    case Format::vti: return "vti";
    case Format::vtp: return "vtp";
    case Format::vts: return "vts";
    default: return "vtk";
  }
}

}  // namespace

extern "C" int fest_vtk_plugin_abi(void) { return FEST_VTK_PLUGIN_ABI; }

extern "C" size_t fest_vtk_plugin_layout(void) { return sizeof(fest::Dataset) * 65536 + sizeof(fest::DataArray); }

extern "C" int fest_vtk_read_dataset(const char* bytes, size_t size, int format, void* dataset, char* message,
                                     size_t message_size) {
  return guarded(message, message_size, [&] {
    const auto f = static_cast<fest::formats::Format>(format);
    vtkSmartPointer<vtkDataSet> vtk = fest::formats::detail::read_vtk_dataset(std::string_view(bytes, size), f);
    *static_cast<fest::Dataset*>(dataset) = fest::formats::from_vtk(vtk, name_of(f));
  });
}

extern "C" int fest_vtk_write_dataset(const void* dataset, int format, int ascii, int zlib, void* bytes,
                                      char* message, size_t message_size) {
  return guarded(message, message_size, [&] {
    fest::formats::DatasetWriteOptions options;
    options.ascii = ascii != 0;
    options.zlib = zlib != 0;
    vtkSmartPointer<vtkDataSet> vtk = fest::formats::to_vtk(*static_cast<const fest::Dataset*>(dataset));
    *static_cast<std::string*>(bytes) =
        fest::formats::detail::write_vtk_dataset(vtk, static_cast<fest::formats::Format>(format), options);
  });
}

extern "C" __attribute__((visibility("default"))) const FestVtkPluginTable* fest_vtk_plugin_table(void) {
  static const FestVtkPluginTable table{FEST_VTK_PLUGIN_ABI, fest_vtk_plugin_layout(), &fest_vtk_read_dataset,
                                        &fest_vtk_write_dataset};
  return &table;
}
