// softobj tongue: shape parameters -> the tongue skeleton JSON (docs/softobj.md §4).
#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/table.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "core/file_io.hpp"
#include "core/parallel_for.hpp"
#include "core/threads.hpp"
#include "mesh_output.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/palate.hpp"
#include "softobj/shrinkwrap.hpp"
#include "softobj/skeleton_json.hpp"
#include "softobj/tongue.hpp"

namespace fest::softobj_tool {

namespace {

void apply_set(softobj::TongueParams& p, const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos) throw usage_error("--set {}: expected name=value", item);
  const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
  const int i = softobj::TongueParams::index_of(name);
  if (i < 0) throw usage_error("--set: unknown parameter {} (x0 y0 z0 l1..l9 a1..a3 c1..c6)", name);
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v)) throw usage_error("--set {}: {} is not a number", name, value);
  p[i] = v;
}

// The one printf conversion of a frame pattern (%d or %0Nd), else a usage error.
std::string frame_name(const std::string& pattern, std::size_t frame) {
  const auto pos = pattern.find('%');
  std::size_t k = pos + 1;
  while (pos != std::string::npos && k < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[k]))) ++k;
  if (pos == std::string::npos || k >= pattern.size() || pattern[k] != 'd' || k - pos > 4 ||
      pattern.find('%', k) != std::string::npos)
    throw usage_error("-o {}: a frame pattern needs exactly one %d or %0Nd (frames/t%04d.ply)", pattern);
  char buf[32];
  std::snprintf(buf, sizeof buf, pattern.substr(pos, k - pos + 1).c_str(), static_cast<int>(frame));
  return pattern.substr(0, pos) + buf + pattern.substr(k + 1);
}

struct Frame {
  double time = 0;
  softobj::TongueParams params;
};

softobj::Palate read_palate(const std::string& path) {
  try {
    return softobj::decode_palate(read_input(path));
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), path));
  }
}

}  // namespace

int run_tongue(const TongueArgs& a) {
  if (!(a.radius > 0)) throw usage_error("--radius must be positive");
  if (a.polygonize) (void)frame_name(a.output, 0);  // usage errors before any work
  softobj::TongueParams neutral = softobj::neutral_tongue();
  for (const auto& s : a.set) apply_set(neutral, s);  // usage errors before reading
  std::vector<Frame> frames;
  if (a.neutral) {
    frames.push_back({0, neutral});
  } else {
    const formats::Input in = formats::load_input(a.input);
    if (in.format != formats::Format::csv && in.format != formats::Format::tsv)
      throw bad_input("tongue parameters are {}, not TSV ({})", formats::format_name(in.format), in.name);
    const Table t = formats::parse(in, formats::read_table);
    if (!a.polygonize && (a.frame < 0 || static_cast<std::size_t>(a.frame) >= t.rows()))
      throw bad_input("frame {} is not in the table ({} rows) ({})", a.frame, t.rows(), in.name);
    if (t.rows() == 0) throw bad_input("the parameter table has no rows ({})", in.name);
    const std::size_t ct = t.find("time");
    const std::size_t first = a.polygonize ? 0 : static_cast<std::size_t>(a.frame);
    const std::size_t last = a.polygonize ? t.rows() : first + 1;
    for (std::size_t r = first; r < last; ++r) {
      Frame f{ct == Table::npos ? static_cast<double>(r) : t.columns[ct][r], softobj::neutral_tongue()};
      for (int i = 0; i < softobj::TongueParams::count; ++i) {
        const char* name = softobj::TongueParams::names()[static_cast<std::size_t>(i)];
        const std::size_t c = t.find(name);
        if (c == Table::npos) throw bad_input("tongue parameters lack column {} ({})", name, in.name);
        const double v = t.columns[c][r];
        if (!std::isfinite(v)) throw bad_input("{} in frame {} is not finite ({})", name, r, in.name);
        f.params[i] = v;
      }
      for (const auto& s : a.set) apply_set(f.params, s);  // --set overrides the row
      frames.push_back(f);
    }
  }
  for (std::size_t r = 0; r < frames.size(); ++r)
    for (int l = 3; l <= 11; ++l)
      if (!(frames[r].params[l] >= 0))
        throw bad_input("length {} is negative ({}) in frame {}", softobj::TongueParams::names()[static_cast<std::size_t>(l)],
                        frames[r].params[l], r);
  std::optional<softobj::Palate> palate;
  if (!a.palate.empty()) palate = read_palate(a.palate);
  const auto layout = a.layout == TongueLayoutChoice::paper9 ? softobj::TongueLayout::paper9 : softobj::TongueLayout::default10;
  if (!a.polygonize) {
    softobj::TongueParams p = frames.front().params;
    if (palate) softobj::palate_pass1(p, *palate, a.radius);
    formats::store_output(a.output, softobj::encode_skeleton(softobj::tongue_skeleton(p, layout, a.radius)), false);
    return 0;
  }
  // Frames are independent (docs/softobj.md §5): polygonised in parallel, written after
  // all succeeded, in frame order.
  std::vector<TriMesh> meshes(frames.size());
  std::vector<std::size_t> fixed(frames.size());
  std::vector<double> volume(frames.size());
  Progress bar("softobj tongue", frames.size(), progress_wanted(a.progress));
  const ProgressFn report = bar.callback();
  ProgressCounter polygonised(report, frames.size());
  parallel_for(frames.size(), resolve_threads(a.threads), [&](std::size_t i) {
    softobj::TongueParams p = frames[i].params;
    if (palate) {
      const auto fx = softobj::palate_pass1(p, *palate, a.radius);
      fixed[i] = static_cast<std::size_t>(fx.sphere + fx.plane);
    }
    const softobj::Field field(softobj::compile_terms(softobj::tongue_skeleton(p, layout, a.radius)));
    softobj::ShrinkwrapOptions o;
    o.iso = 1 / a.radius;
    o.alpha_deg = a.alpha_deg;
    o.lmax = a.lmax;
    o.max_deviation = a.max_deviation;
    o.steps = a.steps;
    try {
      meshes[i] = softobj::shrinkwrap(field, o);
    } catch (const Error& e) {
      throw Error(e.status(), fmt::format("frame {}: {}", i, e.what()));
    }
    if (palate) fixed[i] += softobj::palate_pass2(meshes[i], *palate);
    volume[i] = softobj::measure(meshes[i]).volume;
    polygonised.step();
  });
  polygonised.finish();
  bar.finish();
  std::string manifest = "frame\ttime_s\tfile\tvertices\ttriangles\tvolume_mm3\tpenetrations_fixed\n";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string name = frame_name(a.output, i);
    write_trimesh(meshes[i], mesh_target(name, ""));
    manifest += fmt::format("{}\t{}\t{}\t{}\t{}\t{:.6g}\t{}\n", i, frames[i].time, name, meshes[i].n_vertices(),
                            meshes[i].n_faces(), volume[i], fixed[i]);
  }
  formats::store_output("-", manifest, false);
  return 0;
}

}  // namespace fest::softobj_tool
