// resample mipkernel: the level-0 weights of one mip-map lookup (Fig. 10.12/10.13), as CSV.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "sampling/mip_kernel.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

int run_mipkernel(const MipKernelArgs& a) {
  const MipBuild build = a.build;
  if (a.pos.empty()) throw usage_error("mipkernel needs --pos");
  if (a.dims == 1) {
    std::vector<std::vector<double>> w;
    for (double x : a.pos) w.push_back(mip_kernel_1d(a.level, x, build));
    std::string out = "i";
    for (double x : a.pos) out += fmt::format(",w_{}", x);
    out += "\n";
    for (std::size_t i = 0; i < w[0].size(); ++i) {
      bool any = false;
      for (const auto& col : w) any = any || std::fabs(col[i]) > 1e-15;
      if (!any) continue;
      out += fmt::format("{}", i);
      for (const auto& col : w) out += fmt::format(",{:.9g}", col[i]);
      out += "\n";
    }
    write_output("-", out);
    return 0;
  }
  if (a.dims != 2) throw usage_error("--dims must be 1 or 2");
  if (a.pos.size() != 2) throw usage_error("mipkernel --dims 2 takes --pos X,Y");
  // Separable: the 2-D lookup is bilinear over four blocks, the product of two 1-D kernels.
  const auto wx = mip_kernel_1d(a.level, a.pos[0], build), wy = mip_kernel_1d(a.level, a.pos[1], build);
  std::string out = "i,j,w\n";
  for (std::size_t j = 0; j < wy.size(); ++j)
    for (std::size_t i = 0; i < wx.size(); ++i)
      if (std::fabs(wx[i] * wy[j]) > 1e-15) out += fmt::format("{},{},{:.9g}\n", i, j, wx[i] * wy[j]);
  write_output("-", out);
  return 0;
}

}  // namespace fest::resample_tool
