#include "frames.hpp"

#include <sstream>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "formats/image/image_stream.hpp"

namespace fest::markerpose_tool {

namespace {

void add_file(std::vector<FrameSource>& frames, const std::string& path) {
  FrameSource f;
  f.name = path;
  f.bytes = read_input(path);
  frames.push_back(std::move(f));
}

cv::Mat to_8bit(const cv::Mat& m) {
  cv::Mat out;
  if (m.depth() == CV_8U) return m;
  if (m.depth() == CV_16U) m.convertTo(out, CV_8U, 1.0 / 257.0);
  else m.convertTo(out, CV_8U, 255.0);
  return out;
}

fest::Image decode(const FrameSource& f) {
  try {
    return formats::read_image(f.bytes, formats::detect_format(f.bytes, f.name));
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), f.name));
  }
}

}  // namespace

std::vector<FrameSource> gather_frames(const std::vector<std::string>& inputs, const std::string& list, int width,
                                       int height, const std::string& camera_path) {
  std::vector<FrameSource> frames;
  std::vector<std::string> names = inputs;
  if (!list.empty()) {
    std::istringstream in(read_input(list));
    std::string line;
    while (std::getline(in, line)) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if (!line.empty() && line[0] != '#') names.push_back(line);
    }
    if (names.empty()) throw bad_input("the list names no image ({})", list);
  }
  if (names.empty()) names.push_back("-");
  for (const std::string& n : names) {
    if (!is_stdio(n)) {
      add_file(frames, n);
      continue;
    }
    const std::string all = read_input(n);
    const std::vector<std::string_view> parts = formats::split_image_stream(all);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      FrameSource f;
      f.name = parts.size() == 1 ? "-" : "-#" + std::to_string(k);
      f.bytes = std::string(parts[k]);
      frames.push_back(std::move(f));
    }
  }
  // Sizes from the headers, checked against the camera before any decoding.
  std::size_t wrong = 0;
  const FrameSource* first_wrong = nullptr;
  for (FrameSource& f : frames) {
    formats::ImageHeader h;
    try {
      h = formats::read_image_header(f.bytes, formats::detect_format(f.bytes, f.name));
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), f.name));
    }
    f.width = h.width;
    f.height = h.height;
    if (h.width != width || h.height != height) {
      ++wrong;
      if (!first_wrong) first_wrong = &f;
    }
  }
  if (first_wrong)
    throw bad_input("image is {}x{} but the camera ({}) was calibrated at {}x{}; {} of {} frames differ ({})",
                    first_wrong->width, first_wrong->height, camera_path, width, height, wrong, frames.size(),
                    first_wrong->name);
  return frames;
}

cv::Mat decode_grey(const FrameSource& f) {
  const fest::Image img = decode(f);
  cv::Mat m = to_8bit(img.pixels), grey;
  switch (m.channels()) {
    case 1: grey = m; break;
    case 2: cv::extractChannel(m, grey, 0); break;
    case 3: cv::cvtColor(m, grey, cv::COLOR_RGB2GRAY); break;
    default: cv::cvtColor(m, grey, cv::COLOR_RGBA2GRAY); break;
  }
  return grey;
}

cv::Mat decode_rgb(const FrameSource& f) {
  const fest::Image img = decode(f);
  cv::Mat m = to_8bit(img.pixels), rgb;
  switch (m.channels()) {
    case 1: cv::cvtColor(m, rgb, cv::COLOR_GRAY2RGB); break;
    case 2: {
      cv::Mat g;
      cv::extractChannel(m, g, 0);
      cv::cvtColor(g, rgb, cv::COLOR_GRAY2RGB);
      break;
    }
    case 3: rgb = m.clone(); break;
    default: cv::cvtColor(m, rgb, cv::COLOR_RGBA2RGB); break;
  }
  return rgb;
}

}  // namespace fest::markerpose_tool
