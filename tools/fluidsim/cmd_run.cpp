// fluidsim run: scene JSON -> simulation -> frames (files or the frame stream).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <thread>

#include <omp.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/quote.hpp"
#include "core/progress.hpp"
#include "core/resources.hpp"
#include "core/stopwatch.hpp"
#include "core/tool_main.hpp"
#include "fluidsim/frame.hpp"
#include "fluidsim/operators.hpp"
#include "fluidsim/simulator.hpp"
#include "fluidsim/state_ring.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/volume/volume_io.hpp"
#include "image_data_frame.hpp"
#include "openmp_threads.hpp"
#include "output_names.hpp"
#include "plane_image.hpp"

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;
using nlohmann::json;
using Clock = SteadyClock;

namespace {

Scene load_scene(const std::string& path) {
  const std::string where = input_name(path);
  const std::string text = read_input(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw bad_input("empty scene ({})", where);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw bad_input("scene: {} ({})", json_failure_words(e.what(), e.byte, text), where);
  } catch (const json::exception& e) {  // out_of_range: a number beyond double's range
    throw bad_input("scene: {} ({})", json_failure_words(e.what(), 0, text), where);
  }
  return parse_scene(doc, where);
}

Dataset frame_to_vti(const Frame& f, bool float64) {
  Dataset img = Dataset::image_data({f.size[0], f.size[1], f.size[2]}, {f.spacing, f.spacing, f.spacing}, {0, 0, 0});
  const int C = f.channels();
  int c0 = 0;
  bool have_scalars = false;
  for (const FrameField& ff : f.fields) {
    std::vector<double> values(f.nodes() * std::size_t(ff.components));
    for (std::size_t n = 0; n < f.nodes(); ++n)
      for (int k = 0; k < ff.components; ++k) values[n * std::size_t(ff.components) + std::size_t(k)] = f.data[n * C + c0 + k];
    DataArray arr = DataArray::from_doubles(ff.name, ff.components, values, float64 ? vtk_type::double_ : vtk_type::float_);
    // Active vectors: velocity; active scalars: the first one-component field.
    if (ff.name == "velocity" && ff.components == 3) {
      arr.attribute = 1;
    } else if (ff.components == 1 && !have_scalars) {
      arr.attribute = 0;
      have_scalars = true;
    }
    img.point_data.push_back(std::move(arr));
    c0 += ff.components;
  }
  return img;
}

// 2-D frames as images: one scalar (1 channel) or velocity (u, v, 0).
Image frame_to_image(const Frame& f, const std::string& field) {
  const int c0 = f.channel_of(field);
  int comps = 1;
  for (const auto& ff : f.fields)
    if (ff.name == field) comps = ff.components;
  const int channels = comps == 1 ? 1 : 3;
  cv::Mat m(f.size[1], f.size[0], CV_32FC(channels));
  const int C = f.channels();
  for (int y = 0; y < f.size[1]; ++y)
    for (int x = 0; x < f.size[0]; ++x) {
      float* px = m.ptr<float>(f.size[1] - 1 - y) + static_cast<std::size_t>(x) * channels;
      const std::size_t n = x + static_cast<std::size_t>(f.size[0]) * y;
      for (int k = 0; k < channels; ++k) px[k] = k < comps ? static_cast<float>(f.data[n * C + c0 + k]) : 0.0f;
    }
  return Image{m, ColorSpace::linear};
}

// Reads an init file into a State on the grid of `layout`: velocity (3 components) and
// the scene's scalars by name; absent fields start at zero / the scalar's init value.
State read_init_file(const std::string& path, const Layout& layout, const std::vector<std::string>& scalar_names,
                     const Scene& scene) {
  const std::string bytes = read_input(path);
  if (bytes.empty()) throw bad_input("empty init file ({})", path);
  Frame f;
  if (bytes.rfind("NRRD", 0) == 0) {
    decode_frame(bytes, 0, f, path, 0);
  } else {
    const formats::Input in = formats::recognise(std::string(bytes), path);
    if (in.format != formats::Format::vti) throw bad_input("init file must be a .vti or an NRRD frame ({})", path);
    const Dataset img = formats::parse(in, formats::read_dataset);
    if (img.kind != DatasetKind::image) throw bad_input("init file holds no image data ({})", path);
    read_image_data_frame(img, f, UnnamedArrays::skip);
  }
  if (f.size != layout.size)
    throw bad_input("init file has {}x{}x{} nodes, the scene's grid stores {}x{}x{} ({})", f.size[0], f.size[1],
                    f.size[2], layout.size[0], layout.size[1], layout.size[2], path);
  State s;
  for (int c = 0; c < 3; ++c) s.u[c] = c < layout.dim ? layout.zeros() : Field();
  for (const FrameField& ff : f.fields)
    if (ff.name == "velocity" && ff.components != 3)
      throw bad_input("init file: velocity has {} components, not 3 ({})", ff.components, path);
  if (const int v = f.channel_of("velocity"); v >= 0)
    for (int c = 0; c < layout.dim; ++c) s.u[c] = f.component(v + c);
  for (std::size_t i = 0; i < scalar_names.size(); ++i) {
    const int c = f.channel_of(scalar_names[i]);
    s.s.push_back(c >= 0 ? f.component(c) : Field(layout.count(), scene.scalars[i].init));
  }
  return s;
}

struct Output {
  std::string pattern;
  FrameFormat format = FrameFormat::stream;
};

void write_frame(const Output& out, const Frame& f, const std::string& main_field, bool float64) {
  if (out.format == FrameFormat::stream) {
    const std::string bytes = encode_frame(f);
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
      throw io_error("cannot write the frame stream (stdout)");
    return;
  }
  const std::string path = expand_pattern(out.pattern, f.index);
  if (out.format == FrameFormat::vti) {
    write_output(path, formats::write_dataset(frame_to_vti(f, float64), formats::Format::vti));
  } else if (out.format == FrameFormat::nrrd) {
    // One file per field: f00000_density.nrrd, f00000_velocity.nrrd.
    const auto dot = path.find_last_of('.');
    for (const FrameField& ff : f.fields) {
      const std::string name = path.substr(0, dot) + "_" + ff.name + path.substr(dot);
      if (ff.components == 1) {
        Volume v;
        v.dims = {static_cast<std::size_t>(f.size[0]), static_cast<std::size_t>(f.size[1]),
                  static_cast<std::size_t>(f.size[2])};
        v.spacing = {f.spacing, f.spacing, f.spacing};
        v.type = float64 ? ScalarType::f64 : ScalarType::f32;
        v.voxels = f.component(f.channel_of(ff.name));
        write_output(name, formats::write_volume(v, formats::Format::nrrd));
      } else {
        Frame one = f;
        one.fields = {ff};
        const int c0 = f.channel_of(ff.name), C = f.channels();
        one.data.resize(f.nodes() * ff.components);
        for (std::size_t n = 0; n < f.nodes(); ++n)
          for (int k = 0; k < ff.components; ++k) one.data[n * ff.components + k] = f.data[n * C + c0 + k];
        write_output(name, encode_frame(one));
      }
    }
  } else if (out.format == FrameFormat::pfm || out.format == FrameFormat::exr) {
    write_output(path, formats::write_image(frame_to_image(f, main_field),
                                            out.format == FrameFormat::pfm ? formats::Format::pfm : formats::Format::exr));
  } else {  // png preview with the render defaults
    fluidsim::RenderOptions ro;
    ro.axis = 1;
    ro.spacing = f.spacing;
    ro.sigma = 4.0 / (f.spacing * std::max({f.size[0], f.size[1], f.size[2]}));
    const std::vector<double> values = f.magnitude(main_field);
    const Plane p = render_plane(values, f.size, f.dim, ro);
    double lo = 0.0, hi = 1.0;
    if (f.dim == 2) {
      hi = *std::max_element(p.values.begin(), p.values.end());
      lo = std::min(0.0, *std::min_element(p.values.begin(), p.values.end()));
      if (hi <= lo) hi = lo + 1.0;
    }
    Image img{plane_to_rgb(p, lo, hi, Colormap::inferno, 8), ColorSpace::srgb};
    write_output(path, formats::write_image(img, formats::Format::png));
  }
}

// The scene with the run's flags applied, and the checks that need it (usage errors for
// flags the scene cannot take), in the order a user meets them.
Scene read_run_scene(const RunOptions& o) {
  Scene scene = load_scene(o.scene);
  if (o.frames > 0) scene.frames = o.frames;
  if (o.interp > 0) scene.interp = o.interp;
  for (const std::string& w : scene.warnings) warn("fluidsim", w);
  if (scene.interp > 8) warn("fluidsim", fmt::format("--interp {} > 8 interpolates over long steps (quality)", scene.interp));
  if (o.format != FrameFormat::stream && scene.frames > 1 && !has_index_conversion(o.output))
    throw usage_error("-o \"{}\" needs a %d for {} frames", o.output, scene.frames);
  if ((o.format == FrameFormat::pfm || o.format == FrameFormat::exr) && scene.dim != 2)
    throw usage_error("{} output is for 2-D scenes; use vti or nrrd", o.format == FrameFormat::pfm ? "pfm" : "exr");
  return scene;
}

void warn_odd_periodic_axes(const Scene& scene) {
  for (int a = 0; a < scene.dim; ++a)
    if (scene.bc[a] == Boundary::periodic && scene.dims[a] % 2 == 1)
      warn("fluidsim", fmt::format("periodic axis {} has odd size {}: its parity classes join (no split)", a, scene.dims[a]));
}

// The solver options: the flags' Poisson solver (by default FDM up to 64 nodes an axis,
// FFT above), with a warning where FFT sizes are slow.
SimOptions sim_options(const RunOptions& o, const Scene& scene) {
  int nmax = 0;
  for (int a = 0; a < scene.dim; ++a) nmax = std::max(nmax, scene.dims[a]);
  SimOptions so;
  so.projection.solver = o.poisson ? *o.poisson : (nmax <= 64 ? PoissonSolver::fdm : PoissonSolver::fft);
  so.projection.iters = o.iters;
  so.projection.tol = o.tol;
  so.stam03 = o.order == StepOrder::stam03;
  so.mass_correct = o.mass_correct;

  if (so.projection.solver == PoissonSolver::fft) {
    std::string slow;
    for (int a = 0; a < scene.dim; ++a)
      if (scene.bc[a] == Boundary::closed && !fft_friendly(scene.dims[a]))
        slow += fmt::format("{}{} ({} would do)", slow.empty() ? "" : ", ", scene.dims[a],
                            nearest_fft_friendly(scene.dims[a]));
    if (!slow.empty())
      warn("fluidsim", "fft: n + 1 has a prime factor above 7 for dims " + slow + ": slower transforms");
  }
  return so;
}

// The fields frames carry: the scene's scalars by name, the --fields subset of velocity
// and them, and the one field that 1-field outputs (pfm, exr, png) show.
struct FrameFields {
  std::vector<std::string> scalar_names, fields;
  std::string main_field;
};

FrameFields frame_fields(const RunOptions& o, const Scene& scene) {
  FrameFields ff;
  for (const auto& s : scene.scalars) ff.scalar_names.push_back(s.name);
  if (o.fields.empty()) {
    ff.fields.push_back("velocity");
    for (const auto& n : ff.scalar_names) ff.fields.push_back(n);
  } else {
    for (const std::string& item : o.fields) {
      if (item != "velocity" && std::find(ff.scalar_names.begin(), ff.scalar_names.end(), item) == ff.scalar_names.end())
        throw usage_error("--fields names \"{}\", which the scene does not have", item);
      ff.fields.push_back(item);
    }
  }
  ff.main_field = ff.fields.front();
  for (const auto& f : ff.fields)
    if (f != "velocity") {
      ff.main_field = f;
      break;
    }
  return ff;
}

// An init file: a frame written by fluidsim (VTI or NRRD frame) on the same grid;
// relative names are relative to the scene file's folder.
std::optional<State> init_file_state(const RunOptions& o, const Scene& scene, const Layout& layout,
                                     const std::vector<std::string>& scalar_names) {
  if (scene.init.kind != "file") return std::nullopt;
  std::string path = scene.init.file;
  const auto slash = o.scene.find_last_of('/');
  if (path.front() != '/' && o.scene != "-" && slash != std::string::npos) path = o.scene.substr(0, slash + 1) + path;
  return read_init_file(path, layout, scalar_names, scene);
}

// The simulation levels 0..last_level: from the solver through the 3-slot ring (the
// solver thread runs ahead while this thread interpolates and writes), or, with
// --pipeline off, computed here on demand. Both give the same bytes.
class LevelSource {
 public:
  LevelSource(const Simulator& sim, const std::optional<State>& given, double dt, long last_level, bool pipeline)
      : sim_(sim), given_(given), dt_(dt), last_level_(last_level), pipeline_(pipeline) {
    const int nthreads = omp_threads();
    if (pipeline_) thread_ = std::thread([this, nthreads] { produce(nthreads); });
  }
  ~LevelSource() {
    ring_.cancel();
    if (thread_.joinable()) thread_.join();
  }
  LevelSource(const LevelSource&) = delete;
  LevelSource& operator=(const LevelSource&) = delete;

  const RingEntry& get(long level) {
    if (pipeline_) return ring_.get(level);
    while (inline_.empty() || inline_.back().level < level) {
      if (inline_.empty()) {
        inline_.push_back({0, sim_.initial_state(given_ ? &*given_ : nullptr), {}});
      } else {
        RingEntry next{inline_.back().level + 1, inline_.back().state, {}};
        next.stats = sim_.step(next.state, dt_);
        inline_.push_back(std::move(next));
      }
    }
    for (const RingEntry& e : inline_)
      if (e.level == level) return e;
    throw runtime_failure("internal: level {} was released", level);
  }

  void release_below(long level) {
    if (pipeline_) {
      ring_.release_below(level);
      return;
    }
    while (!inline_.empty() && inline_.front().level < level) inline_.pop_front();
  }

 private:
  void produce(int nthreads) {
    try {
      omp_set_num_threads(nthreads);  // a new thread starts from the default
      State s = sim_.initial_state(given_ ? &*given_ : nullptr);
      ring_.push({0, s, {}});
      for (long l = 1; l <= last_level_ && !ring_.cancelled(); ++l) {
        const StepStats st = sim_.step(s, dt_);
        ring_.push({l, s, st});
      }
      ring_.finish();
    } catch (...) {
      ring_.finish(std::current_exception());
    }
  }

  const Simulator& sim_;
  const std::optional<State>& given_;
  const double dt_;
  const long last_level_;
  const bool pipeline_;
  StateRing ring_{3};
  std::deque<RingEntry> inline_;  // --pipeline off
  std::thread thread_;
};

// The figures of a run as frames are written: per-frame stats lines, divergence and
// speed maxima, and the summed step times.
struct RunTotals {
  json stats_lines = json::array();
  std::string stats_text;
  double max_div = 0.0, max_div_rel = 0.0, peak_speed = 0.0;
  double total_ms[7] = {0, 0, 0, 0, 0, 0, 0};  // force advect diffuse project scalars interp write
  long sim_steps = 0, counted = 0;
};

// Adds a level's step figures to the totals once; returns them when new.
bool account(RunTotals& t, const RingEntry& e, StepStats& last) {
  if (e.level <= t.counted) return false;
  t.counted = e.level;
  const StepStats& st = e.stats;
  ++t.sim_steps;
  t.total_ms[0] += st.ms_force;
  t.total_ms[1] += st.ms_advect;
  t.total_ms[2] += st.ms_diffuse;
  t.total_ms[3] += st.ms_project;
  t.total_ms[4] += st.ms_scalars;
  t.max_div = std::max(t.max_div, st.projection.max_div_after);
  if (st.projection.max_div_before > 0)
    t.max_div_rel = std::max(t.max_div_rel, st.projection.max_div_after / st.projection.max_div_before);
  last = st;
  return true;
}

// One frame's line of --stats: its time, speed, energy, divergence, scalar masses and the
// times of the step that made it (zero for frames of a level already counted).
json frame_stats_line(const Layout& layout, const State& state, const FrameFields& ff, long f, const Scene& scene, long level,
                      int phase, double speed, const StepStats* step, double ms_interp, double ms_write) {
  Field div;
  divergence(layout, state.u, div);
  json line = {{"frame", f},
               {"time", f * scene.frame_dt},
               {"sim_step", level},
               {"interpolated", phase != 0},
               {"max_speed", speed},
               {"kinetic_energy", kinetic_energy(layout, state.u)},
               {"max_div", max_abs(div)}};
  for (std::size_t i = 0; i < ff.scalar_names.size(); ++i)
    line["mass." + ff.scalar_names[i]] = weighted_sum(layout, state.s[i]);
  line["ms"] = {{"force", step ? step->ms_force : 0.0},   {"advect", step ? step->ms_advect : 0.0},
                {"diffuse", step ? step->ms_diffuse : 0.0}, {"project", step ? step->ms_project : 0.0},
                {"scalars", step ? step->ms_scalars : 0.0}, {"interp", ms_interp},
                {"write", ms_write}};
  return line;
}

// Frame by frame: the level(s) it lies on, the state at its time (interpolated between
// levels), the frame written, its figures added to the totals.
void write_frames(const RunOptions& o, const Scene& scene, const Layout& layout, const FrameFields& ff, LevelSource& levels,
                  RunTotals& t) {
  Output out;
  out.pattern = o.output;
  out.format = o.format;
  const int K = scene.interp;
  Progress progress("fluidsim", static_cast<std::uint64_t>(scene.frames), progress_wanted(o.progress));
  State blended;  // the interpolated frames' buffers, reused from frame to frame
  for (long f = 0; f < scene.frames; ++f) {
    const long level = f / K;
    const int phase = static_cast<int>(f % K);
    StepStats last{};
    bool stepped = false;
    const RingEntry& a = levels.get(level);
    stepped = account(t, a, last) || stepped;
    const RingEntry* b = nullptr;
    if (phase != 0) {
      b = &levels.get(level + 1);
      stepped = account(t, *b, last) || stepped;
    }
    auto t0 = Clock::now();
    // Frame time f * frame_dt: the state itself, or (1 - a) X^n + a X^(n+1).
    if (phase != 0) blend(a.state, b->state, static_cast<double>(phase) / K, blended);
    const State& frame_state = phase == 0 ? a.state : blended;
    const double ms_interp = phase == 0 ? 0.0 : ms_since(t0);
    t.total_ms[5] += ms_interp;
    Frame frame = make_frame(layout, frame_state, ff.scalar_names, ff.fields, f, f * scene.frame_dt);
    frame.float64 = o.float64;
    t0 = Clock::now();
    write_frame(out, frame, ff.main_field, frame.float64);
    const double ms_write = ms_since(t0);
    t.total_ms[6] += ms_write;

    const double speed = max_speed(layout, frame_state.u);
    t.peak_speed = std::max(t.peak_speed, speed);
    if (!o.stats.empty() || !o.report.empty()) {
      json line = frame_stats_line(layout, frame_state, ff, f, scene, level, phase, speed, stepped ? &last : nullptr,
                                   ms_interp, ms_write);
      t.stats_text += line.dump() + "\n";
      t.stats_lines.push_back(std::move(line));
    }
    levels.release_below(level);
    progress.advance();
  }
  progress.finish();
}

void write_run_report(const RunOptions& o, const Scene& scene, const SimOptions& so, const FrameFields& ff,
                      const RunTotals& t, double wall_ms) {
  const int K = scene.interp;
  const double steps = std::max<long>(1, t.sim_steps);
  const double* ms = t.total_ms;
  json rep = {{"frames", scene.frames},
              {"simulation_steps", t.sim_steps},
              {"interp", K},
              {"dt", K * scene.frame_dt},
              {"wall_ms", wall_ms},
              {"max_div", t.max_div},
              {"max_div_rel", t.max_div_rel},
              {"max_speed", t.peak_speed},
              {"solver", poisson_name(so.projection.solver)},
              {"order", o.order == StepOrder::stam03 ? "stam03" : "paper"},
              {"threads", omp_threads()},
              {"pipeline", o.pipeline},
              {"dims", std::vector<int>(scene.dims.begin(), scene.dims.begin() + scene.dim)},
              {"mean_ms",
               {{"force", ms[0] / steps},
                {"advect", ms[1] / steps},
                {"diffuse", ms[2] / steps},
                {"project", ms[3] / steps},
                {"scalars", ms[4] / steps},
                {"step", (ms[0] + ms[1] + ms[2] + ms[3] + ms[4]) / steps},
                {"interp_frame", ms[5] / std::max<double>(1.0, scene.frames - std::ceil(scene.frames / double(K)))},
                {"write_frame", ms[6] / scene.frames}}},
              {"peak_rss_mb", peak_rss_kb() / 1024.0}};
  for (const auto& n : ff.scalar_names) rep["mass." + n] = t.stats_lines.back()["mass." + n];
  write_output(o.report, rep.dump(2) + "\n");
}

}  // namespace

int run_command(const RunOptions& o) {
  set_threads(o.threads);
  // The flags were checked in main.cpp (usage errors); now the scene (bad input).
  const Scene scene = read_run_scene(o);
  const Layout layout = scene.layout();
  warn_odd_periodic_axes(scene);
  const SimOptions so = sim_options(o, scene);
  const FrameFields ff = frame_fields(o, scene);
  const Simulator sim(scene, so);
  const std::optional<State> given = init_file_state(o, scene, layout, ff.scalar_names);

  const int K = scene.interp;
  // The last simulation level a frame needs (the next one when the last frame lies
  // between two states).
  const long last_frame = scene.frames - 1;
  const long last_level = last_frame / K + (last_frame % K ? 1 : 0);
  LevelSource levels(sim, given, K * scene.frame_dt, last_level, o.pipeline);

  RunTotals totals;
  const auto t_start = Clock::now();
  write_frames(o, scene, layout, ff, levels, totals);
  if (!o.stats.empty()) write_output(o.stats, totals.stats_text);
  if (!o.report.empty()) write_run_report(o, scene, so, ff, totals, ms_since(t_start));
  return 0;
}

}  // namespace fest::fluidsim_tool
