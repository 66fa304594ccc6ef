// markerpose detect: frames -> markers, IDs, corners and poses (docs/markerpose.md §2-4),
// optionally the AR overlay (§5.2).
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/parallel_for.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "frames.hpp"
#include "markers/camera_codec.hpp"
#include "markers/overlay.hpp"
#include "markers/tracker.hpp"
#include "pose_json.hpp"

namespace fest::markerpose_tool {

namespace {

using nlohmann::json;

markers::CameraModel load_camera(const std::string& path) {
  const std::string text = read_input(path);
  try {
    return markers::decode_camera_json(text);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), path));
  }
}

std::vector<markers::PatternTemplate> load_patterns(const std::vector<std::string>& paths) {
  std::vector<markers::PatternTemplate> out;
  for (const std::string& p : paths) {
    FrameSource f;
    f.name = p;
    f.bytes = read_input(p);
    try {
      out.push_back(markers::make_pattern(decode_grey(f), p));
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), p));
    }
  }
  return out;
}

reflectance::TriangleMesh load_overlay_mesh(const std::string& path, double scale) {
  const Mesh m = formats::parse(formats::load_input(path), formats::read_mesh);
  reflectance::TriangleMesh tm;
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    tm.vertices.emplace_back(scale * p[0], scale * p[1], scale * p[2]);
  }
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> idx;
    for (auto v : m.fv_range(f)) idx.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t k = 1; k + 1 < idx.size(); ++k) tm.triangles.push_back({idx[0], idx[k], idx[k + 1]});
  }
  if (tm.triangles.empty()) throw bad_input("the overlay mesh has no faces ({})", path);
  for (const auto& v : tm.vertices)
    if (!v.allFinite()) throw bad_input("the overlay mesh has a non-finite vertex ({})", path);
  reflectance::compute_vertex_normals(tm);
  return tm;
}

std::string frame_path(const std::string& pattern, std::size_t frame, std::size_t frames) {
  if (pattern.find("%d") == std::string::npos) {
    if (frames > 1) throw usage_error("--overlay-out needs %d in its name for {} frames", frames);
    return pattern;
  }
  std::string p = pattern;
  p.replace(p.find("%d"), 2, std::to_string(frame));
  return p;
}

}  // namespace

int detect_command(const DetectOptions& o) {
  if (!(o.size > 0) || !std::isfinite(o.size)) throw usage_error("--size {}: the marker side must be positive", o.size);
  if (!o.overlay.empty() && o.overlay_out.empty()) throw usage_error("--overlay needs --overlay-out FILE.png");
  if (o.overlay.empty() && !o.overlay_out.empty()) throw usage_error("--overlay-out needs --overlay MESH");
  const int threads = resolve_threads(o.threads);
  const markers::CameraModel camera = load_camera(o.camera);

  std::vector<markers::PatternTemplate> patterns;
  markers::DetectorOptions det;
  if (!o.patterns.empty()) {
    patterns = load_patterns(o.patterns);
    det.patterns = &patterns;
    det.min_pattern_ncc = o.min_ncc;
  } else {
    try {
      det.dictionary = &markers::dictionary(o.dict);
    } catch (const Error& e) {
      throw Error(Status::usage, std::string("--dict: ") + e.what());
    }
  }
  det.camera = &camera;
  det.quads.min_side_px = o.min_side_px;
  std::optional<reflectance::TriangleMesh> mesh;
  if (!o.overlay.empty()) mesh = load_overlay_mesh(o.overlay, o.overlay_scale);

  const std::vector<FrameSource> frames = gather_frames(o.inputs, o.list, camera.width, camera.height, o.camera);
  const std::size_t n = frames.size();
  if (mesh) frame_path(o.overlay_out, 0, n);  // a usage error before any work

  // Detection per frame in parallel; poses in frame order (the tracker is sequential).
  const Stopwatch detect_clock;
  std::vector<std::vector<markers::Detection>> found(n);
  Progress bar("markerpose detect", n, progress_wanted(o.progress));
  ProgressCounter searched(bar.callback(), n);
  parallel_for(n, threads, [&](std::size_t i) {
    found[i] = markers::detect_markers(decode_grey(frames[i]), det);
    searched.step();
  });
  bar.finish();
  const double detect_ms = detect_clock.ms();

  markers::PoseTracker tracker;
  std::vector<std::vector<MarkerResult>> results(n);
  std::size_t total = 0, with_markers = 0, switched = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (const markers::Detection& d : found[i]) {
      MarkerResult r;
      r.detection = d;
      r.estimate = markers::estimate_square_pose(camera, d.corners, o.size);
      r.pose = n > 1 ? tracker.update(d.id, r.estimate, &r.switched) : r.estimate.pose;
      switched += r.switched;
      results[i].push_back(r);
    }
    total += results[i].size();
    with_markers += !results[i].empty();
  }

  const bool pattern = !patterns.empty();
  std::string out;
  if (n == 1 && !o.lines) {
    // One marker per line inside the list: readable, and still one JSON document.
    out = "[";
    for (std::size_t k = 0; k < results[0].size(); ++k)
      out += (k ? ",\n  " : "\n  ") + marker_json(results[0][k], pattern, o.size).dump();
    out += results[0].empty() ? "]\n" : "\n]\n";
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const MarkerResult& r : results[i]) list.push_back(marker_json(r, pattern, o.size));
      out += nlohmann::ordered_json{{"frame", i}, {"image", frames[i].name}, {"markers", list}}.dump() + "\n";
    }
  }

  if (mesh) {
    parallel_for(n, threads, [&](std::size_t i) {
      cv::Mat rgb = decode_rgb(frames[i]);
      std::vector<markers::Pose> poses;
      for (const MarkerResult& r : results[i]) poses.push_back(r.pose);
      markers::draw_overlay(rgb, *mesh, camera, poses);
      const std::string path = frame_path(o.overlay_out, i, n);
      fest::Image img{rgb, ColorSpace::srgb};
      write_output(path, formats::write_image(img, formats::output_format_from_path(path).format));
    });
  }
  write_output(o.output, out);

  if (!o.report.empty()) {
    const double ms = detect_ms;
    json rep = {{"frames", n},
                {"markers", total},
                {"frames_with_markers", with_markers},
                {"sequence_switches", switched},
                {"dictionary", pattern ? "patterns" : o.dict},
                {"threads", threads},
                {"detect_ms_total", ms},
                {"detect_ms_per_frame", n ? ms / double(n) : 0.0}};
    write_output(o.report, rep.dump(2) + "\n");
  }
  if (!o.quiet && total == 0) warn("markerpose", fmt::format("no marker found in {} frame(s)", n));
  return 0;
}

}  // namespace fest::markerpose_tool
