// volwave edges: the multiscale edge map of a volume as a volume of its own.

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "volume_input.hpp"
#include "wavelet/edges.hpp"

namespace fest::volwave_tool {

int edges_command(const EdgesOptions& o) {
  if (o.min_scales > o.scales) throw usage_error("--min-scales {} exceeds --scales {}", o.min_scales, o.scales);
  const Volume v = read_any_volume(o.input, o.select);
  wavelet::EdgeOptions eo;
  eo.scales = o.scales;
  eo.threshold = o.threshold;
  eo.min_scales = o.min_scales;
  eo.threads = resolve_threads(o.threads);
  Progress bar("volwave edges", 0, progress_wanted(o.progress));
  eo.progress = bar.callback();
  const wavelet::EdgeMap e = wavelet::multiscale_edges(v, eo);
  bar.finish();
  Volume out = v;
  out.type = ScalarType::f32;
  out.voxels = e.modulus;
  if (!o.points.empty()) {
    // Sub-voxel points in voxel coordinates (i, j, k) and in world coordinates.
    std::string csv = "i,j,k,x,y,z,modulus,alpha\n";
    for (const auto& p : e.points) {
      const auto w = v.world(p.position[0], p.position[1], p.position[2]);
      csv += fmt::format("{:.4f},{:.4f},{:.4f},{:.6g},{:.6g},{:.6g},{:.6g},{:.4f}\n", p.position[0], p.position[1],
                         p.position[2], w[0], w[1], w[2], p.modulus, p.alpha);
    }
    write_output(o.points, csv);
  }
  write_any_volume(out, o.output, o.to);
  if (!o.report.empty()) {
    nlohmann::json r = {{"input", o.input},
                        {"dimensions", v.dims},
                        {"scales", eo.scales},
                        {"threshold", e.threshold},
                        {"maxima_per_scale", e.maxima_per_scale},
                        {"edge_voxels", e.points.size()}};
    write_output(o.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::volwave_tool
