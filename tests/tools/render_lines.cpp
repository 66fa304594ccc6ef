// Test and example tooling: draws lemtrace's CSV output (line,seed,i,x,y,z,t,cell,type,
// speed) as a picture a person can look at -- an orthographic view along z, lines
// coloured by speed (viridis), on white -- with OpenCV.
//
//   render_lines LINES.csv OUT.png [SIZE]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

int main(int argc, char** argv) {
  return fest::run_tool("render_lines", [&] {
    if (argc < 3) throw fest::usage_error("usage: render_lines LINES.csv OUT.png [SIZE]");
    const int size = argc > 3 ? std::atoi(argv[3]) : 900;
    if (size < 64 || size > 8192) throw fest::usage_error("SIZE {} is outside 64..8192", size);
    const fest::formats::Input in = fest::formats::load_input(argv[1]);
    const fest::Table t = fest::formats::parse(in, fest::formats::read_table);
    const std::size_t cl = t.find("line"), cx = t.find("x"), cy = t.find("y"), cs = t.find("speed");
    if (cl == fest::Table::npos || cx == fest::Table::npos || cy == fest::Table::npos || cs == fest::Table::npos)
      throw fest::bad_input("{}: not lemtrace CSV (needs line, x, y, speed)", argv[1]);
    const auto& L = t.columns[cl];
    const auto& X = t.columns[cx];
    const auto& Y = t.columns[cy];
    const auto& S = t.columns[cs];
    if (X.empty()) throw fest::bad_input("{}: no points", argv[1]);
    const double x0 = *std::min_element(X.begin(), X.end()), x1 = *std::max_element(X.begin(), X.end());
    const double y0 = *std::min_element(Y.begin(), Y.end()), y1 = *std::max_element(Y.begin(), Y.end());
    const double s1 = std::max(*std::max_element(S.begin(), S.end()), 1e-300);
    const double extent = std::max({x1 - x0, y1 - y0, 1e-300});
    const int margin = size / 20;
    const double scale = (size - 2 * margin) / extent;
    cv::Mat image(size, size, CV_8UC3, cv::Scalar(255, 255, 255));
    // Speed -> viridis through OpenCV's colour map on a 256-entry ramp.
    cv::Mat ramp(1, 256, CV_8UC1), colours;
    for (int i = 0; i < 256; ++i) ramp.at<uchar>(0, i) = static_cast<uchar>(i);
    cv::applyColorMap(ramp, colours, cv::COLORMAP_VIRIDIS);
    auto pixel = [&](std::size_t i) {
      return cv::Point2d(margin + (X[i] - x0) * scale, size - margin - (Y[i] - y0) * scale);
    };
    for (std::size_t i = 1; i < X.size(); ++i) {
      if (L[i] != L[i - 1]) continue;
      const int c = std::clamp(static_cast<int>(255.0 * S[i] / s1), 0, 255);
      const cv::Vec3b col = colours.at<cv::Vec3b>(0, c);
      cv::line(image, pixel(i - 1) * 16, pixel(i) * 16, cv::Scalar(col[0], col[1], col[2]), 1, cv::LINE_AA, 4);
    }
    cv::rectangle(image, cv::Point(margin - 1, margin - 1), cv::Point(size - margin, size - margin),
                  cv::Scalar(160, 160, 160));
    std::vector<uchar> png;
    if (!cv::imencode(".png", image, png)) throw fest::runtime_failure("PNG encoding failed");
    fest::write_output(argv[2], std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
    return 0;
  });
}
