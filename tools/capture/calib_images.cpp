#include "calib_images.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {

using nlohmann::json;
using namespace fest::capture;

namespace {

void check_size(const cv::Mat& m, cv::Size& size, const std::string& first, const std::string& path) {
  if (size.area() == 0) {
    size = m.size();
    return;
  }
  if (m.size() != size)
    throw bad_input("image is {}x{}, {} is {}x{}: all views must come from one camera setting ({})", m.cols, m.rows,
                    first, size.width, size.height, path);
}

double number_at(const json& doc, const char* key, const std::string& path) {
  if (!doc.contains(key) || !doc[key].is_number()) throw bad_input("camera: '{}' missing or not a number ({})", key, path);
  return doc[key].get<double>();
}

}  // namespace

void note(bool quiet, const std::string& message) {
  if (!quiet) warn("capture", message);
}

GreyImage read_grey(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::image)
    throw bad_input("{} data where an image was expected ({})", formats::kind_name(formats::kind_of(in.format)), path);
  const Image image = formats::parse(in, formats::read_image);
  return GreyImage{to_gray_float(image.pixels), to_gray8(image.pixels)};
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

json json_array(const cv::Matx33d& m) {
  json a = json::array();
  for (int i = 0; i < 9; ++i) a.push_back(m.val[i]);
  return a;
}

Intrinsics read_camera(const std::string& path) {
  const json doc = formats::parse(formats::load_input(path), formats::read_json_document);
  if (!doc.is_object()) throw bad_input("camera: not a JSON object ({})", path);
  Intrinsics c;
  if (!doc.contains("K") || !doc["K"].is_array() || doc["K"].size() != 9)
    throw bad_input("camera: 'K' must hold 9 numbers ({})", path);
  for (int i = 0; i < 9; ++i) {
    if (!doc["K"][std::size_t(i)].is_number()) throw bad_input("camera: K[{}] is not a number ({})", i, path);
    c.K.val[i] = doc["K"][std::size_t(i)].get<double>();
  }
  if (doc.contains("dist")) {
    const json& d = doc["dist"];
    if (!d.is_array() || d.size() > 5) throw bad_input("camera: 'dist' must hold up to 5 numbers ({})", path);
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!d[i].is_number()) throw bad_input("camera: dist[{}] is not a number ({})", i, path);
      c.dist[int(i)] = d[i].get<double>();
    }
  }
  c.width = int(number_at(doc, "width", path));
  c.height = int(number_at(doc, "height", path));
  if (!(c.K(0, 0) > 0) || !(c.K(1, 1) > 0) || c.K(2, 2) != 1 || c.width <= 0 || c.height <= 0)
    throw bad_input("camera: K must have positive focal lengths and K[8] = 1, width and height positive ({})", path);
  return c;
}

void check_camera_size(const Intrinsics& cam, const cv::Mat& m, const std::string& camera_path, const std::string& path) {
  if (m.cols != cam.width || m.rows != cam.height)
    throw bad_input("image is {}x{} but the camera ({}) was calibrated at {}x{} ({})", m.cols, m.rows, camera_path,
                    cam.width, cam.height, path);
}

void emit(const json& doc) { write_output("-", formats::write_json(doc)); }

BoardViews find_boards(const std::vector<std::string>& images, const BoardSpec& board, bool quiet,
                       const std::function<void(const cv::Mat&, const std::string&)>& check) {
  BoardViews v;
  for (const std::string& path : images) {
    const GreyImage g = read_grey(path);
    check_size(g.grey8, v.size, images.front(), path);
    if (check) check(g.grey8, path);
    auto corners = find_board_corners(g.grey8, board);
    if (corners.empty()) {
      v.missing.push_back(path);
      continue;
    }
    v.used.push_back(path);
    v.corners.push_back(std::move(corners));
  }
  if (v.used.empty())
    throw bad_input("no {}x{} board found in any image: {}", board.cols, board.rows, joined(v.missing));
  for (const std::string& m : v.missing) note(quiet, fmt::format("no {}x{} board found; image left out ({})", board.cols, board.rows, m));
  return v;
}

void emit_board_result(nlohmann::json doc, const std::string& board_name, const nlohmann::json& views,
                       const BoardViews& found) {
  doc["board"] = board_name;
  doc["views"] = views;
  doc["left_out"] = found.missing;
  emit(doc);
}

}  // namespace fest::capture_tool
