#include "stack_files.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"

namespace fest::hdrmerge_tool {
namespace {

bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

const char* const kChannelNames[] = {"gR", "gG", "gB"};

}  // namespace

double parse_exposure_time(const std::string& text) {
  double value = 0;
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) {
    if (parse_number(text, value) && value > 0) return value;
  } else {
    double numerator = 0, denominator = 0;
    if (parse_number(text.substr(0, slash), numerator) && parse_number(text.substr(slash + 1), denominator) &&
        numerator > 0 && denominator > 0)
      return numerator / denominator;
  }
  throw usage_error("--times: '{}' is not a positive exposure time (seconds, e.g. 0.004 or 1/250)", text);
}

hdr::ExposureStack read_stack(const std::vector<std::string>& paths, const std::vector<double>& times,
                              const ProgressFn& progress) {
  hdr::ExposureStack stack;
  stack.times = times;
  if (paths.size() != times.size())
    throw bad_input("{} images but {} exposure times in --times", paths.size(), times.size());
  for (const std::string& path : paths) {
    const formats::Input in = formats::load_input(path);
    if (formats::kind_of(in.format) != formats::Kind::image)
      throw bad_input("{} data where an image was expected ({})", formats::kind_name(formats::kind_of(in.format)), path);
    Image image = formats::parse(in, formats::read_image);
    const cv::Mat& m = image.pixels;
    if (m.depth() != CV_8U)
      throw bad_input("{}-bit image; response recovery needs 8-bit exposures ({})", m.depth() == CV_16U ? 16 : 32,
                      path);
    if (m.channels() != 1 && m.channels() != 3)
      throw bad_input("{} channels; expected grey or RGB ({})", m.channels(), path);
    if (!stack.images.empty() &&
        (m.size() != stack.images.front().size() || m.channels() != stack.images.front().channels()))
      throw bad_input("image is {}x{}x{}, the first of the series {}x{}x{} ({})", m.cols, m.rows, m.channels(),
                      stack.images.front().cols, stack.images.front().rows, stack.images.front().channels(), path);
    stack.images.push_back(m);
    if (progress) progress(stack.images.size(), paths.size());
  }
  hdr::validate_stack(stack);
  return stack;
}

Table response_table(const hdr::Response& response) {
  Table t;
  std::vector<double> z(hdr::kCodes);
  for (int i = 0; i < hdr::kCodes; ++i) z[std::size_t(i)] = i;
  t.add_column("z", z);
  for (int c = 0; c < response.channels(); ++c)
    t.add_column(response.channels() == 1 ? "g" : kChannelNames[c],
                 std::vector<double>(response.g[std::size_t(c)].begin(), response.g[std::size_t(c)].end()));
  return t;
}

hdr::Response response_from_table(const Table& table) {
  if (table.rows() != std::size_t(hdr::kCodes))
    throw bad_input("response table has {} rows, expected {}", table.rows(), hdr::kCodes);
  const std::size_t z = table.find("z");
  if (z == Table::npos) throw bad_input("response table has no column z");
  for (int i = 0; i < hdr::kCodes; ++i)
    if (table.columns[z][std::size_t(i)] != i) throw bad_input("response table: row {} has z = {}", i + 1, table.columns[z][std::size_t(i)]);
  std::vector<std::string> names;
  if (table.find("g") != Table::npos)
    names = {"g"};
  else
    names = {kChannelNames[0], kChannelNames[1], kChannelNames[2]};
  hdr::Response r;
  for (const std::string& name : names) {
    const std::size_t col = table.find(name);
    if (col == Table::npos) throw bad_input("response table needs columns z,g or z,gR,gG,gB (no {})", name);
    hdr::Curve g{};
    for (int i = 0; i < hdr::kCodes; ++i) {
      g[std::size_t(i)] = table.columns[col][std::size_t(i)];
      if (!std::isfinite(g[std::size_t(i)])) throw bad_input("response table: {} at z = {} is not finite", name, i);
    }
    r.g.push_back(g);
  }
  return r;
}

}  // namespace fest::hdrmerge_tool
