// lbmsim voxelize: a closed mesh -> uint8 flag volume (docs/lbmsim.md 2.8).
#include <cstdio>

#include "case_loader.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/detect.hpp"
#include "formats/volume/volume_io.hpp"
#include "lbm/voxelize.hpp"

namespace fest::lbmsim_tool {

int voxelize_command(const VoxelizeOptions& o) {
  if (o.size.size() != 3) throw usage_error("--size needs nx,ny,nz");
  formats::Format format = formats::Format::nrrd;
  if (o.output != "-" && !o.output.empty()) {
    const std::string& p = o.output;
    auto ends = [&](const std::string& e) { return p.size() >= e.size() && p.compare(p.size() - e.size(), e.size(), e) == 0; };
    if (ends(".nrrd")) format = formats::Format::nrrd;
    else if (ends(".mha")) format = formats::Format::mha;
    else if (ends(".nii")) format = formats::Format::nifti;
    else throw usage_error("flag volume output must be .nrrd, .mha or .nii (\"{}\")", p);
  }
  const lbm::TriangleSoup soup = read_closed_mesh(o.mesh);
  lbm::Flags flags;
  flags.size = {o.size[0], o.size[1], o.size[2]};
  flags.id.assign(static_cast<std::size_t>(o.size[0]) * o.size[1] * o.size[2], 0);
  lbm::VoxelizeOptions vo;
  vo.fit_box = o.fit_box;
  vo.margin = o.margin;
  std::size_t marked = 0;
  try {
    marked = lbm::voxelize(soup, vo, flags);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), o.mesh));
  }
  if (marked == 0) warn("lbmsim", "no node lies inside the mesh (check --size and --fit)");
  Volume v;
  v.dims = {flags.size[0] + 0ul, flags.size[1] + 0ul, flags.size[2] + 0ul};
  v.type = ScalarType::u8;
  v.voxels.assign(flags.id.begin(), flags.id.end());
  write_output(o.output.empty() ? "-" : o.output, formats::write_volume(v, format));
  return 0;
}

}  // namespace fest::lbmsim_tool
