#include "capture/silhouette.hpp"

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fest::capture {

cv::Mat silhouette_mask(const cv::Mat& image) {
  if ((image.depth() != CV_8U && image.depth() != CV_16U) || (image.channels() != 1 && image.channels() != 3))
    throw bad_input("silhouette: expected an 8 or 16-bit grey or RGB image");
  cv::Mat grey;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_RGB2GRAY);
  else grey = image;
  // Otsu in OpenCV takes 8 bits; 16-bit values keep their top byte.
  if (grey.depth() == CV_16U) grey.convertTo(grey, CV_8U, 1.0 / 257.0);
  double lo = 0, hi = 0;
  cv::minMaxLoc(grey, &lo, &hi);
  if (hi - lo < 8) throw bad_input("silhouette: the shot has no contrast (grey values {}..{})", lo, hi);
  cv::Mat dark;
  cv::threshold(grey, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);

  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(dark, labels, stats, centroids, 8, CV_32S);
  int best = 0, best_area = 0;
  for (int i = 1; i < n; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > best_area) best_area = stats.at<int>(i, cv::CC_STAT_AREA), best = i;
  if (best == 0) throw bad_input("silhouette: no dark object against the backlight");
  cv::Mat mask = labels == best;

  // Holes: background regions not connected to the border. Flood the background from a
  // one-pixel frame around the image; what the flood does not reach is inside.
  cv::Mat framed(mask.rows + 2, mask.cols + 2, CV_8U, cv::Scalar(0));
  mask.copyTo(framed(cv::Rect(1, 1, mask.cols, mask.rows)));
  cv::floodFill(framed, cv::Point(0, 0), cv::Scalar(128));
  cv::Mat inside = framed(cv::Rect(1, 1, mask.cols, mask.rows)) != 128;
  return inside;
}

}  // namespace fest::capture
