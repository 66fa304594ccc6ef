// markerpose gen: synthetic marker images at known poses with their ground truth
// (docs/markerpose.md §5.1).
#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "frames.hpp"
#include "marker_art.hpp"
#include "markers/camera_codec.hpp"
#include "markers/synth.hpp"

namespace fest::markerpose_tool {

namespace {

using nlohmann::json;

markers::CameraModel gen_camera(const GenOptions& o) {
  if (!o.camera.empty()) {
    const std::string text = read_input(o.camera);
    try {
      return markers::decode_camera_json(text);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), o.camera));
    }
  }
  markers::CameraModel c;
  c.K = cv::Matx33d(o.focal, 0, (o.width - 1) / 2.0, 0, o.focal, (o.height - 1) / 2.0, 0, 0, 1);
  c.width = o.width;
  c.height = o.height;
  return c;
}

formats::Format image_format(const std::string& path, const std::optional<formats::Format>& to, bool stream) {
  if (to) return *to;
  if (is_stdio(path) || stream) return formats::output_format_from_name("pgm").format;
  return formats::output_format_from_path(path).format;
}

std::string encode(const cv::Mat& grey, formats::Format f) { return formats::write_image({grey, ColorSpace::srgb}, f); }

json truth_json(const markers::CameraModel& cam, const markers::PlacedMarker& m, int id, std::size_t frame) {
  const markers::Corners c = markers::project_corners(cam, m.pose, m.side);
  json corners = json::array(), R = json::array();
  double side_px = 0;
  for (int k = 0; k < 4; ++k) {
    corners.push_back({c[k].x, c[k].y});
    side_px += cv::norm(c[(k + 1) % 4] - c[k]) / 4;
  }
  for (int i = 0; i < 9; ++i) R.push_back(m.pose.R.val[i]);
  const cv::Vec3d r = markers::rotation_vector(m.pose.R);
  return {{"frame", frame}, {"id", id},           {"size", m.side},
          {"corners", corners}, {"rvec", {r[0], r[1], r[2]}}, {"tvec", {m.pose.t[0], m.pose.t[1], m.pose.t[2]}},
          {"R", R},           {"side_px", side_px}};
}

}  // namespace

int gen_command(const GenOptions& o) {
  if (!(o.size > 0)) throw usage_error("--size {}: the marker side must be positive", o.size);
  if (!(o.distance > 0)) throw usage_error("--distance {}: must be positive", o.distance);
  if (!(o.white > o.black)) throw usage_error("--white must be above --black");
  const markers::CameraModel cam = gen_camera(o);
  markers::PlacedMarker m;
  m.side = o.size;
  if (!o.pattern.empty()) {
    FrameSource f;
    f.name = o.pattern;
    f.bytes = read_input(o.pattern);
    f.width = 0;
    m.art.picture = decode_grey(f);
    m.art.quiet_zone = 0;
  } else {
    m.art = art_from_flags(o.dict, o.id);
  }
  markers::Degradation d;
  d.black = o.black;
  d.white = o.white;
  d.gradient = o.gradient;
  d.occlusion = o.occlusion;
  d.blur_sigma = o.blur;
  d.noise_sigma = o.noise;
  d.clutter = o.clutter;
  cv::Mat photo;
  if (!o.background.empty()) {
    FrameSource f;
    f.name = o.background;
    f.bytes = read_input(o.background);
    photo = decode_grey(f);
    if (photo.cols != cam.width || photo.rows != cam.height)
      throw bad_input("the background is {}x{} but the camera is {}x{} ({})", photo.cols, photo.rows, cam.width,
                      cam.height, o.background);
  }
  const bool pattern_name = o.output.find("%d") != std::string::npos;
  const bool stream = o.frames > 1 && !pattern_name;
  const formats::Format fmt = image_format(o.output, o.to, stream);
  if (stream && fmt != formats::output_format_from_name("pgm").format &&
      fmt != formats::output_format_from_name("png").format)
    throw usage_error("a stream of {} frames is written as png or pgm (--to), or name files with %d", o.frames);
  std::string stream_bytes, truth;
  for (int i = 0; i < o.frames; ++i) {
    const double u = (o.u < 0 ? cam.K(0, 2) : o.u) + i * o.u_step, v = o.v < 0 ? cam.K(1, 2) : o.v;
    m.pose = markers::pose_facing(cam, u, v, o.distance, o.tilt + i * o.tilt_step, o.axis, o.roll + i * o.roll_step);
    const cv::Mat img = markers::render_scene(cam, {m}, d, o.seed + static_cast<std::uint64_t>(i), photo);
    const std::string bytes = encode(img, fmt);
    if (o.frames == 1) {
      stream_bytes = bytes;
    } else if (pattern_name) {
      std::string p = o.output;
      p.replace(p.find("%d"), 2, std::to_string(i));
      write_output(p, bytes);
    } else {
      stream_bytes += bytes;
    }
    json t = truth_json(cam, m, o.pattern.empty() ? o.id : 0, static_cast<std::size_t>(i));
    truth += o.frames == 1 ? t.dump(2) + "\n" : t.dump() + "\n";
  }
  if (!stream_bytes.empty()) write_output(o.output, stream_bytes);
  if (!o.truth.empty()) write_output(o.truth, truth);
  return 0;
}

}  // namespace fest::markerpose_tool
