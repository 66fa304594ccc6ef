// capture's V4L2 frame conversions at camera sizes, against OpenCV in the same run:
// YUYV 4:2:2 -> RGB (lib/capture/pixel_formats, BT.601 limited range) against
// cv::cvtColor(COLOR_YUV2RGB_YUYV), and MJPEG decoding (devices/v4l2_frame through
// formats/ and libjpeg-turbo) against cv::imdecode. One JSON line per case: median
// milliseconds per frame over the runs, and the largest difference from the anchor.
// A camera at 30 frames/s leaves 33 ms a frame. Not run by CTest.
//
//   build/bin/bench_v4l2_frames [RUNS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/pixel_formats.hpp"
#include "devices/v4l2_frame.hpp"
#include "formats/image/image_io.hpp"

namespace {

double median_ms(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  return t[t.size() / 2];
}

// A camera-like picture: smooth shading plus sensor noise, studio-range YUYV.
cv::Mat scene_yuyv(int w, int h) {
  cv::Mat luma(h, w, CV_8UC1), chroma(h, w, CV_8UC1), noise(h, w, CV_8UC1), yuyv;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      luma.at<uchar>(r, c) = uchar(16 + (219 * (r + c)) / (w + h));
      chroma.at<uchar>(r, c) = uchar(c % 2 ? 128 + (100 * r) / h - 50 : 128 + (100 * c) / w - 50);
    }
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0, 3);
  luma += noise;
  cv::merge(std::vector<cv::Mat>{luma, chroma}, yuyv);
  return yuyv;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{640, 480}, {1920, 1080}}) {
    const cv::Mat yuyv = scene_yuyv(w, h);
    const fest::capture::RawFrame raw{fest::capture::fourcc_yuyv, w, h, int(yuyv.step),
                                      std::string_view(reinterpret_cast<const char*>(yuyv.data), yuyv.total() * 2)};
    fest::Image ours;
    cv::Mat anchor;
    const double fest_ms = median_ms(runs, [&] { ours = fest::capture::unpack_raw_frame(raw); });
    const double cv_ms = median_ms(runs, [&] { cv::cvtColor(yuyv, anchor, cv::COLOR_YUV2RGB_YUYV); });
    std::printf(
        "{\"bench\":\"v4l2_frames\",\"case\":\"yuyv_to_rgb\",\"width\":%d,\"height\":%d,\"runs\":%d,\"fest_ms\":%.3f,"
        "\"anchor\":\"opencv_cvtColor\",\"anchor_ms\":%.3f,\"max_abs_diff\":%.0f}\n",
        w, h, runs, fest_ms, cv_ms, cv::norm(ours.pixels, anchor, cv::NORM_INF));

    cv::Mat rgb;
    cv::cvtColor(yuyv, rgb, cv::COLOR_YUV2RGB_YUYV);
    fest::formats::ImageWriteOptions o;
    o.jpeg_quality = 85;
    const std::string jpeg = fest::formats::write_image(fest::Image{rgb, fest::ColorSpace::srgb}, fest::formats::Format::jpeg, o);
    const fest::capture::RawFrame mj{fest::capture::fourcc_mjpg, w, h, 0, jpeg};
    cv::Mat bgr;
    const std::vector<uchar> buf(jpeg.begin(), jpeg.end());
    const double fest_mj = median_ms(runs, [&] { ours = fest::devices::decode_v4l2_frame(mj); });
    const double cv_mj = median_ms(runs, [&] { bgr = cv::imdecode(buf, cv::IMREAD_COLOR); });
    cv::cvtColor(bgr, bgr, cv::COLOR_BGR2RGB);
    std::printf(
        "{\"bench\":\"v4l2_frames\",\"case\":\"mjpeg_decode\",\"width\":%d,\"height\":%d,\"bytes\":%zu,\"runs\":%d,"
        "\"fest_ms\":%.3f,\"anchor\":\"opencv_imdecode\",\"anchor_ms\":%.3f,\"max_abs_diff\":%.0f}\n",
        w, h, jpeg.size(), runs, fest_mj, cv_mj, cv::norm(ours.pixels, bgr, cv::NORM_INF));
  }
  return 0;
}
