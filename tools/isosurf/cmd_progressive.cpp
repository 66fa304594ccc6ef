// isosurf progressive: a sequence of crack-free meshes, coarse first (--errors), or one
// adaptive mesh per focus position (--focus-path); docs/isosurf.md "Progressive mode".
// The volume and its min-max pyramid are built once.
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "isosurface/adaptive.hpp"
#include "isosurface/marching_cubes.hpp"
#include "isosurface/mesh_stats.hpp"
#include "load_grid.hpp"
#include "surface_io.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

namespace fest::isosurf_tool {
namespace {

using Clock = SteadyClock;

std::vector<std::array<double, 3>> read_path(const std::string& path) {
  const std::string text = read_input(path);
  std::vector<std::array<double, 3>> out;
  std::stringstream ss(text);
  int line_no = 0;
  for (std::string line; std::getline(ss, line);) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::array<double, 3> p{};
    char* end = nullptr;
    const char* c = line.c_str();
    bool ok = true;
    for (int a = 0; a < 3 && ok; ++a) {
      p[a] = std::strtod(c, &end);
      ok = end != c && std::isfinite(p[a]) && (a == 2 || *end == ',');
      c = end + 1;
    }
    if (!ok) {
      if (out.empty() && line_no == 1) continue;  // a header
      throw bad_input("focus path line {}: x,y,z expected ({})", line_no, path);
    }
    out.push_back(p);
  }
  if (out.empty()) throw bad_input("focus path has no positions ({})", path);
  return out;
}

}  // namespace

int run_progressive(const ExactOptions& o, const AdaptiveArgs& a, const ProgressiveArgs& p) {
  if (p.errors.empty() == p.focus_path.empty()) throw usage_error("progressive needs exactly one of --errors and --focus-path");
  if (o.output.empty() || o.output == "-") throw usage_error("progressive writes a directory: give -o DIR");
  const std::string format = o.to.empty() ? "ply" : output_format(o.to, "");
  const int threads = resolve_threads(o.threads);
  const std::vector<double>& errors = p.errors;
  std::vector<std::array<double, 3>> path;
  if (!p.errors.empty()) {
    for (std::size_t k = 0; k < errors.size(); ++k)
      if (!(errors[k] >= 0)) throw usage_error("--errors takes values >= 0 separated by commas, not {}", errors[k]);
    for (std::size_t k = 1; k < errors.size(); ++k)
      if (!(errors[k] < errors[k - 1]))
        throw usage_error("--errors must be descending (coarse first), not {} after {}", errors[k], errors[k - 1]);
  } else {
    path = read_path(p.focus_path);
  }
  const LoadedGrid in = load_grid(o);
  std::error_code ec;
  std::filesystem::create_directories(o.output, ec);
  if (ec || !std::filesystem::is_directory(o.output)) throw io_error("cannot create the output directory {}: {}", o.output, ec.message());
  auto t0 = Clock::now();
  const volume_pyramid::MinMaxPyramid pyramid(in.grid, threads);
  const double t_build = seconds_since(t0);
  isosurface::AdaptiveOptions ao;
  ao.face_rule = o.face_rule;
  ao.triangulation = o.tri;
  ao.threads = threads;
  ao.focus_radius = a.focus_radius;
  ao.error_growth = a.error_growth;
  ao.max_level = a.max_level;
  ao.edge_rule = a.edge_rule;
  ao.focus = a.focus;
  const std::size_t count = errors.empty() ? path.size() : errors.size();
  nlohmann::json levels = nlohmann::json::array();
  std::size_t cumulative = 0;
  Progress bar("isosurf progressive", count, progress_wanted(o.progress));
  for (std::size_t k = 0; k < count; ++k) {
    t0 = Clock::now();
    isosurface::Surface s;
    if (!errors.empty()) ao.max_error = errors[k];
    else ao.focus = path[k], ao.max_error = std::numeric_limits<double>::infinity();
    if (!errors.empty() && errors[k] == 0 && !ao.focus) {
      isosurface::ExtractOptions eo;  // tolerance 0 everywhere: the exact surface itself
      eo.face_rule = ao.face_rule, eo.triangulation = ao.triangulation, eo.threads = threads;
      s = isosurface::extract_isosurface(in.grid, in.iso, eo, &pyramid);
    } else {
      s = isosurface::extract_adaptive(in.grid, in.iso, ao, pyramid).surface;
    }
    const double seconds = seconds_since(t0);
    const std::string bytes = encode_surface(s, format, o.qbits);
    char name[32];
    std::snprintf(name, sizeof name, "%s_%02zu.%s", errors.empty() ? "frame" : "level", k, format == "plya" ? "ply" : format.c_str());
    write_output((std::filesystem::path(o.output) / name).string(), bytes);
    cumulative += bytes.size();
    const auto m = isosurface::mesh_stats(s);
    nlohmann::json j = {{"file", name}, {"vertices", s.vertices()}, {"triangles", s.triangles.size()}, {"closed", m.closed},
                        {"bytes", bytes.size()}, {"cumulative_bytes", cumulative}, {"seconds", seconds}};
    if (!errors.empty()) j["max_error"] = errors[k];
    else j["focus"] = path[k];
    levels.push_back(j);
    bar.advance();
  }
  bar.finish();
  nlohmann::json manifest = {{"iso", in.iso}, {"source", in.source}, {"format", format}, {"build_s", t_build},
                             {errors.empty() ? "frames" : "levels", levels}};
  write_output((std::filesystem::path(o.output) / "manifest.json").string(), manifest.dump(2) + "\n");
  return 0;
}

}  // namespace fest::isosurf_tool
