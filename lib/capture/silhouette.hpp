#pragma once
// The object's mask from a backlit silhouette shot (docs/hdrmerge.md §5): the object
// is dark against a bright background. Otsu's threshold on the grey values, the largest
// dark connected component, its holes filled.

#include <opencv2/core.hpp>

namespace fest::capture {

// image: 8 or 16-bit, 1 or 3 channels (R,G,B). Returns CV_8UC1, 255 = object, 0 = not.
// Throws bad_input for other types and for a shot without contrast (no object found).
cv::Mat silhouette_mask(const cv::Mat& image);

}  // namespace fest::capture
