// PNG, PFM and TIFF through OpenCV's imgcodecs, with the BGR <-> RGB swap at the
// boundary and the libraries' console output silenced.
#include <climits>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"
#include "formats/image/quiet_stderr.hpp"

namespace fest::formats::image_detail {
namespace {

int depth_of(const ImageHeader& h) { return h.is_float ? CV_32F : (h.bits == 16 ? CV_16U : CV_8U); }

const char* depth_name(int depth) {
  return depth == CV_8U ? "8-bit" : depth == CV_16U ? "16-bit" : depth == CV_32F ? "32-bit float" : "other";
}

// OpenCV's channel order to fest's (or back: the swaps are their own inverse).
cv::Mat swap_red_blue(const cv::Mat& m) {
  cv::Mat out;
  if (m.channels() == 3) cv::cvtColor(m, out, cv::COLOR_BGR2RGB);
  else if (m.channels() == 4) cv::cvtColor(m, out, cv::COLOR_BGRA2RGBA);
  else out = m;
  return out;
}

}  // namespace

cv::Mat decode_with_opencv(std::string_view bytes, const ImageHeader& expected, const char* what) {
  if (bytes.size() > std::size_t(INT_MAX)) throw bad_input("{} data: file larger than 2 GiB", what);
  cv::Mat decoded;
  {
    QuietStderr quiet;
    try {
      // imdecode only reads the buffer; the Mat header just wraps it without a copy.
      const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
      decoded = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception& e) {
      throw bad_input("{} data: decoder failed: {}", what, e.err);
    }
  }
  if (decoded.empty()) throw bad_input("{} data: corrupt or truncated pixel data", what);
  if (decoded.cols != expected.width || decoded.rows != expected.height)
    throw bad_input("{} data: decoded {} x {} pixels, header says {} x {}", what, decoded.cols, decoded.rows,
                    expected.width, expected.height);
  if (decoded.depth() != depth_of(expected))
    throw bad_input("{} data: decoded {} samples, header says {}", what, depth_name(decoded.depth()),
                    depth_name(depth_of(expected)));
  if (expected.channels == 2 && decoded.channels() == 4) {
    // libpng expands grey + alpha to BGRA with B = G = R; keep grey and alpha.
    cv::Mat grey_alpha(decoded.size(), CV_MAKETYPE(decoded.depth(), 2));
    const int from_to[] = {0, 0, 3, 1};
    cv::mixChannels(&decoded, 1, &grey_alpha, 1, from_to, 2);
    return grey_alpha;
  }
  return swap_red_blue(decoded);
}

std::string encode_with_opencv(const cv::Mat& rgb, const char* extension, const std::vector<int>& params) {
  std::vector<uchar> encoded;
  bool ok = false;
  {
    QuietStderr quiet;
    try {
      ok = cv::imencode(extension, swap_red_blue(rgb), encoded, params);
    } catch (const cv::Exception& e) {
      throw bad_input("cannot write {}: {}", extension + 1, e.err);
    }
  }
  if (!ok) throw bad_input("cannot write {}: the encoder failed", extension + 1);
  return std::string(encoded.begin(), encoded.end());
}

}  // namespace fest::formats::image_detail
