#include "formats/dataset/vtk_plugin_loader.hpp"

#include "core/dataset.hpp"
#include "core/error.hpp"
#include "formats/dataset/vtk_plugin_api.h"
#include "formats/plugin_loader.hpp"

namespace fest::formats::detail {

const VtkPlugin& vtk_plugin() {
  // Debian 12's VTK runtime (libvtk9.1 holds libvtkCommonCore-9.1.so.1 and the IO
  // modules): a plugin that does not load almost always means a missing libvtk.
  static constexpr PluginModule kModule{"libfest_vtk_plugin.so", "fest_vtk_plugin_table", "VTK dataset support",
                                        "libvtk9.1"};
  const FestVtkPluginTable* table = plugin_table<FestVtkPluginTable>(kModule);
  // The table carries fest::Dataset across: a module built from another version of
  // core/dataset.hpp must not be called.
  if (table->abi != FEST_VTK_PLUGIN_ABI || table->layout != sizeof(Dataset) * 65536 + sizeof(DataArray))
    throw io_error("VTK dataset support is not available (libfest_vtk_plugin.so is from another fest version); "
                   "reinstall fest");
  static const VtkPlugin plugin{table->read_dataset, table->write_dataset};
  return plugin;
}

}  // namespace fest::formats::detail
