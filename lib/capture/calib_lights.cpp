#include "capture/calib_lights.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fest::capture {

namespace {

constexpr double kPi = 3.14159265358979323846;

float sample(const cv::Mat& img, double x, double y) {
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= img.cols || y0 + 1 >= img.rows) return 0.f;
  const float fx = float(x - x0), fy = float(y - y0);
  const float* r0 = img.ptr<float>(y0);
  const float* r1 = img.ptr<float>(y0 + 1);
  return (r0[x0] * (1 - fx) + r0[x0 + 1] * fx) * (1 - fy) + (r1[x0] * (1 - fx) + r1[x0 + 1] * fx) * fy;
}

// Sub-pixel outline: along rays from the blob's centre, the steepest fall of
// brightness (parabola through the extreme of the derivative).
std::vector<cv::Point2d> refine_outline(const cv::Mat& grey, cv::Point2d c, double r0) {
  std::vector<cv::Point2d> out;
  const int rays = std::max(64, int(2 * kPi * r0));
  const double step = 0.1, reach = std::max(3.0, 0.15 * r0);
  const int samples = int(2 * reach / step) + 1;
  std::vector<double> profile(static_cast<std::size_t>(samples));
  for (int i = 0; i < rays; ++i) {
    const double phi = 2 * kPi * i / rays, dx = std::cos(phi), dy = std::sin(phi);
    for (int s = 0; s < samples; ++s) {
      const double r = r0 - reach + s * step;
      profile[std::size_t(s)] = sample(grey, c.x + r * dx, c.y + r * dy);
    }
    int best = -1;
    double steepest = 0;
    for (int s = 1; s + 1 < samples; ++s) {
      const double d = profile[std::size_t(s + 1)] - profile[std::size_t(s - 1)];
      if (d < steepest) steepest = d, best = s;
    }
    if (best < 2 || best + 2 >= samples) continue;
    const double dm = profile[std::size_t(best)] - profile[std::size_t(best - 2)];
    const double d0 = steepest;
    const double dp = profile[std::size_t(best + 2)] - profile[std::size_t(best)];
    const double denom = dm - 2 * d0 + dp;
    const double shift = denom != 0 ? std::clamp(0.5 * (dm - dp) / denom, -0.5, 0.5) : 0.0;
    const double r = r0 - reach + (best + shift) * step;
    out.emplace_back(c.x + r * dx, c.y + r * dy);
  }
  return out;
}

// The brightest blob inside the disc: its peak, then the intensity-weighted centroid
// of the connected pixels above half-way between the disc's median and the peak.
bool find_highlight(const cv::Mat& grey, cv::Point2d c, double radius, cv::Point2d& centroid, double& peak) {
  const double r = radius - 2;
  if (r <= 1) return false;
  cv::Mat disc = cv::Mat::zeros(grey.size(), CV_8U);
  cv::circle(disc, cv::Point(int(std::lround(c.x)), int(std::lround(c.y))), int(r), cv::Scalar(255), cv::FILLED);
  double lo = 0, hi = 0;
  cv::Point at;
  cv::minMaxLoc(grey, &lo, &hi, nullptr, &at, disc);
  std::vector<float> inside;
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      if (disc.at<std::uint8_t>(y, x)) inside.push_back(grey.at<float>(y, x));
  if (inside.empty()) return false;
  std::nth_element(inside.begin(), inside.begin() + long(inside.size() / 2), inside.end());
  const double median = inside[inside.size() / 2];
  if (hi - median < 0.05) return false;  // no spot clearly brighter than the sphere
  const float threshold = float(median + 0.5 * (hi - median));
  cv::Mat above = (grey > threshold) & disc;
  cv::Mat labels;
  cv::connectedComponents(above, labels, 8, CV_32S);
  const int label = labels.at<int>(at);
  double sw = 0, sx = 0, sy = 0;
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      if (labels.at<int>(y, x) == label) {
        const double w = grey.at<float>(y, x) - threshold;
        sw += w, sx += w * x, sy += w * y;
      }
  if (sw <= 0) return false;
  centroid = cv::Point2d(sx / sw, sy / sw);
  peak = hi;
  // The mirror point is where the highlight peaks; a highlight foreshortened on the
  // sphere is lopsided, so its centroid lies a little off the peak. Unless it is
  // saturated (flat top), take the vertex of a quadratic fitted by least squares to
  // the log of the excess brightness over the 5x5 pixels around the brightest one.
  if (hi < 0.98 && at.x >= 2 && at.y >= 2 && at.x + 2 < grey.cols && at.y + 2 < grey.rows) {
    cv::Mat A(25, 6, CV_64F), b(25, 1, CV_64F);
    int row = 0;
    bool positive = true;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx, ++row) {
        const double v = grey.at<float>(at.y + dy, at.x + dx) - median;
        positive = positive && v > 0;
        const double q[6] = {1.0, double(dx), double(dy), double(dx * dx), double(dx * dy), double(dy * dy)};
        for (int k = 0; k < 6; ++k) A.at<double>(row, k) = q[k];
        b.at<double>(row) = std::log(std::max(v, 1e-6));
      }
    cv::Mat f;
    if (positive && cv::solve(A, b, f, cv::DECOMP_SVD)) {
      // Vertex of c0 + c1 x + c2 y + c3 x^2 + c4 xy + c5 y^2 (a maximum: negative definite).
      const double a = 2 * f.at<double>(3), bb = f.at<double>(4), cc = 2 * f.at<double>(5);
      const double det = a * cc - bb * bb;
      if (a < 0 && det > 0) {
        const double x = (-f.at<double>(1) * cc + f.at<double>(2) * bb) / det;
        const double y = (-f.at<double>(2) * a + f.at<double>(1) * bb) / det;
        if (std::abs(x) <= 1 && std::abs(y) <= 1) centroid = cv::Point2d(at.x + x, at.y + y);
      }
    }
  }
  return true;
}

cv::Vec3d unit_ray(const cv::Point2d& pixel, const Intrinsics& camera) {
  std::vector<cv::Point2d> in{pixel}, out;
  cv::undistortPoints(in, out, cv::Mat(camera.K), cv::Mat(camera.dist).reshape(1, 1), cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 1e-12));
  return cv::normalize(cv::Vec3d(out[0].x, out[0].y, 1));
}

}  // namespace

std::vector<SphereImage> detect_spheres(const cv::Mat& grey, const SphereDetectOptions& options) {
  CV_Assert(grey.type() == CV_32F);
  cv::Mat g8;
  grey.convertTo(g8, CV_8U, 255);
  cv::Mat mask;
  cv::threshold(g8, mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::vector<SphereImage> found;
  for (const auto& contour : contours) {
    const double area = cv::contourArea(contour), perimeter = cv::arcLength(contour, true);
    if (perimeter <= 0) continue;
    const cv::Rect box = cv::boundingRect(contour);
    if (box.x <= 1 || box.y <= 1 || box.br().x >= grey.cols - 1 || box.br().y >= grey.rows - 1) continue;
    const double radius = std::sqrt(area / kPi);
    if (radius < options.min_radius_px || 4 * kPi * area / (perimeter * perimeter) < options.min_circularity) continue;
    const cv::Moments mo = cv::moments(contour);
    SphereImage s;
    const cv::Point2d c(mo.m10 / mo.m00, mo.m01 / mo.m00);
    s.outline = refine_outline(grey, c, radius);
    // A highlight close to the rim can pull single rays onto its own edge: drop points
    // off the median radius by more than a pixel.
    std::vector<double> radii;
    for (const auto& p : s.outline) radii.push_back(cv::norm(p - c));
    std::vector<double> sorted = radii;
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    const double median = sorted.empty() ? 0 : sorted[sorted.size() / 2];
    std::vector<cv::Point2d> kept;
    for (std::size_t i = 0; i < radii.size(); ++i)
      if (std::abs(radii[i] - median) <= 1.0) kept.push_back(s.outline[i]);
    s.outline = std::move(kept);
    if (s.outline.size() < 16) continue;
    cv::Point2d mean(0, 0);
    for (const auto& p : s.outline) mean += p;
    s.centre = mean * (1.0 / double(s.outline.size()));
    double rsum = 0;
    for (const auto& p : s.outline) rsum += cv::norm(p - s.centre);
    s.radius = rsum / double(s.outline.size());
    if (!find_highlight(grey, s.centre, s.radius, s.highlight, s.highlight_peak)) continue;
    found.push_back(std::move(s));
  }
  std::sort(found.begin(), found.end(), [](const SphereImage& a, const SphereImage& b) { return a.centre.x < b.centre.x; });
  return found;
}

SphereRay sphere_ray(const SphereImage& sphere, const Intrinsics& camera, double radius_mm) {
  // The outline is where rays graze the sphere: a cone about the direction c of the
  // centre with half-angle alpha, r_i . c = cos(alpha) for every outline ray r_i.
  // Linear least squares in w = c / cos(alpha): r_i . w = 1.
  cv::Matx33d N = cv::Matx33d::zeros();
  cv::Vec3d rhs(0, 0, 0);
  for (const auto& p : sphere.outline) {
    const cv::Vec3d r = unit_ray(p, camera);
    N += r * r.t();
    rhs += r;
  }
  const cv::Vec3d w = N.solve(rhs, cv::DECOMP_CHOLESKY);
  const double cos_a = 1 / cv::norm(w);
  if (!(cos_a > 0 && cos_a < 1)) throw bad_input("sphere outline at ({:.1f}, {:.1f}) px is not a circle", sphere.centre.x, sphere.centre.y);
  const double sin_a = std::sqrt(1 - cos_a * cos_a);
  SphereRay ray;
  ray.centre = cv::normalize(w) * (radius_mm / sin_a);
  // Viewing ray through the highlight, its first hit on the sphere (the nearest
  // point on the sphere where detection noise puts the ray just outside it).
  const cv::Vec3d v = unit_ray(sphere.highlight, camera);
  const double b = v.dot(ray.centre), disc = b * b - ray.centre.dot(ray.centre) + radius_mm * radius_mm;
  const double t = b - std::sqrt(std::max(0.0, disc));
  ray.origin = v * t;
  const cv::Vec3d n = cv::normalize(ray.origin - ray.centre);
  ray.direction = cv::normalize(v - 2 * v.dot(n) * n);
  return ray;
}

LightFit triangulate_light(const std::vector<SphereRay>& rays) {
  if (rays.size() < 2)
    throw bad_input("{} sphere highlight{}; a light position needs at least 2 (two spheres, or one sphere in two places)",
                    rays.size(), rays.size() == 1 ? "" : "s");
  cv::Matx33d A = cv::Matx33d::zeros();
  cv::Vec3d b(0, 0, 0);
  for (const SphereRay& r : rays) {
    const cv::Matx33d P = cv::Matx33d::eye() - r.direction * r.direction.t();
    A += P;
    b += P * r.origin;
  }
  cv::Mat values;
  cv::eigen(cv::Mat(A), values);
  // The smallest eigenvalue is about sum sin^2 of the angles between the rays: below
  // sin^2(1 degree) per ray the intersection is too ill-conditioned to mean anything.
  const double smallest = values.at<double>(2);
  const double limit = double(rays.size()) * std::pow(std::sin(kPi / 180), 2) * 0.5;
  if (smallest < limit)
    throw bad_input("the rays toward the light are nearly parallel; place the spheres farther apart");
  LightFit fit;
  fit.position = A.solve(b, cv::DECOMP_CHOLESKY);
  double sum2 = 0;
  for (const SphereRay& r : rays) {
    const cv::Vec3d d = (cv::Matx33d::eye() - r.direction * r.direction.t()) * (fit.position - r.origin);
    fit.ray_distance_mm.push_back(cv::norm(d));
    sum2 += d.dot(d);
  }
  fit.residual_rms_mm = std::sqrt(sum2 / double(rays.size()));
  return fit;
}

}  // namespace fest::capture
