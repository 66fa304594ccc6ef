#include "commands.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "ffd/joints.hpp"
#include "ffd/lattice.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

#include "mesh_lattice_io.hpp"

namespace fest::ffd_tool {

int run_animate(const AnimateOptions& o) {
  if (!(o.fps > 0 && o.fps <= 1000)) throw usage_error("--fps {} is outside (0, 1000]", o.fps);
  frame_name(o.output, 0);  // validates the pattern
  const int threads = resolve_threads(o.threads);
  const ffd::Outside outside = o.outside;
  // Keys: "time lattice_file" rows, times strictly increasing; all lattices share the box.
  std::vector<std::pair<double, Lattice>> keys;
  {
    std::istringstream in(read_input(o.keys));
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line)) {
      ++n;
      std::istringstream row(line);
      std::string t, file;
      if (!(row >> t) || t[0] == '#' || t == "time") continue;
      double time = 0;
      try {
        time = std::stod(t);
      } catch (const std::exception&) {
        throw bad_input("keys line {}: '{}' is not a time ({})", n, t, o.keys);
      }
      if (!(row >> file)) throw bad_input("keys line {}: expected 'time lattice_file' ({})", n, o.keys);
      if (!keys.empty() && !(time > keys.back().first)) throw bad_input("keys line {}: times must increase ({})", n, o.keys);
      Lattice l = load_lattice(file);
      const ffd::Deformer d(l);
      l = d.lattice();
      if (!keys.empty()) {
        const Lattice& f = keys.front().second;
        if (l.dims != f.dims || l.basis != f.basis || !l.origin.isApprox(f.origin, 0) || l.axes != f.axes)
          throw bad_input("keys line {}: lattice box, dims or basis differ from the first key ({})", n, file);
      }
      keys.emplace_back(time, l);
    }
  }
  if (keys.empty()) throw bad_input("no key lattices ({})", o.keys);
  formats::Format format;
  Mesh mesh = load_mesh(o.input, &format);
  const std::vector<Eigen::Vector3d> rest = points_of(mesh);
  const double t0 = keys.front().first, duration = keys.back().first - t0;
  const long frames = static_cast<long>(std::floor(duration * o.fps + 1e-9)) + 1;
  std::string manifest = "frame\ttime\tfile\n";
  std::size_t seg = 0;
  Progress bar("ffd animate", static_cast<std::uint64_t>(frames), progress_wanted(o.progress));
  for (long f = 0; f < frames; ++f) {
    const double t = t0 + static_cast<double>(f) / o.fps;
    while (seg + 1 < keys.size() && t > keys[seg + 1].first) ++seg;
    Lattice l = keys[seg].second;
    if (seg + 1 < keys.size()) {
      // Linear interpolation of displacements between the bracketing keys.
      const double a = (t - keys[seg].first) / (keys[seg + 1].first - keys[seg].first);
      if (a > 0)
        for (std::size_t i = 0; i < l.displacement.size(); ++i)
          l.displacement[i] = (1 - a) * keys[seg].second.displacement[i] + a * keys[seg + 1].second.displacement[i];
    }
    const ffd::Deformer d(l);
    std::vector<Eigen::Vector3d> p = rest;  // every frame from the rest mesh
    ffd::apply_all(d, p, outside, threads);
    set_points(mesh, p);
    update_normals(mesh, NormalsMode::recompute, nullptr, rest, outside);
    const std::string name = frame_name(o.output, f);
    const formats::OutputFormat of = output_format("", name, format);
    formats::store_output(name, formats::write_mesh(mesh, of.format), of.gzip);
    manifest += fmt::format("{}\t{}\t{}\n", f, t, name);
    bar.advance();
  }
  bar.finish();
  write_output(o.manifest, manifest);
  return 0;
}

}  // namespace fest::ffd_tool
