#include "brdffit/lumitexel_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/parallel_for.hpp"
#include "reflectance/rasterizer.hpp"

namespace fest::brdffit {
namespace {

using reflectance::Fragments;
using reflectance::PinholeCamera;
using reflectance::TriangleMesh;

bool same_camera(const PinholeCamera& a, const PinholeCamera& b) {
  return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.width == b.width && a.height == b.height &&
         a.R == b.R && a.t == b.t && a.dist == b.dist;
}

// Index of the distinct camera of every image (views x lights share cameras).
std::vector<std::size_t> distinct_cameras(const std::vector<ImageView>& views, std::vector<std::size_t>& first_image) {
  std::vector<std::size_t> of(views.size());
  for (std::size_t k = 0; k < views.size(); ++k) {
    std::size_t c = 0;
    while (c < first_image.size() && !same_camera(views[first_image[c]].camera, views[k].camera)) ++c;
    if (c == first_image.size()) first_image.push_back(k);
    of[k] = c;
  }
  return of;
}

bool front_facing(const TriangleMesh& mesh, std::size_t t, const Eigen::Vector3d& eye) {
  const auto& tri = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.vertices[tri[0]];
  const Eigen::Vector3d n = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
  return n.dot(eye - a) > 0;
}

Fragments depth_only(const TriangleMesh& mesh, const PinholeCamera& cam, int threads) {
  reflectance::RasterOptions o;
  o.threads = threads;
  o.barycentrics = false;
  return reflectance::rasterize(mesh, cam, o);
}

// Bilinear lookup of the radiance at a (distorted) image position; false when a tap lies
// outside the image, the mask or the valid pixels, or is not finite.
bool resample(const ImagePixels& img, const Eigen::Vector2d& at, Eigen::Vector3d& out, bool& nonfinite) {
  const int x0 = static_cast<int>(std::floor(at.x())), y0 = static_cast<int>(std::floor(at.y()));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= img.radiance.cols || y0 + 1 >= img.radiance.rows) return false;
  const double ax = at.x() - x0, ay = at.y() - y0;
  out.setZero();
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      const int x = x0 + dx, y = y0 + dy;
      if (!img.mask.empty() && img.mask.at<std::uint8_t>(y, x) == 0) return false;
      if (!img.valid.empty()) {
        const double v = img.valid.depth() == CV_8U ? img.valid.at<std::uint8_t>(y, x) : img.valid.at<float>(y, x);
        if (!(v > 0)) return false;
      }
      const cv::Vec3f& L = img.radiance.at<cv::Vec3f>(y, x);
      if (!std::isfinite(L[0]) || !std::isfinite(L[1]) || !std::isfinite(L[2])) {
        nonfinite = true;
        return false;
      }
      const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
      out += w * Eigen::Vector3d(L[0], L[1], L[2]);
    }
  return true;
}

void check_pixels(const ImagePixels& img, const ImageView& view, std::size_t k) {
  const PinholeCamera& c = view.camera;
  if (img.radiance.cols != c.width || img.radiance.rows != c.height)
    throw bad_input("image {} is {}x{} but its camera is {}x{}", k, img.radiance.cols, img.radiance.rows, c.width,
                    c.height);
  if (img.radiance.type() != CV_32FC3) throw bad_input("image {} is not float RGB", k);
  if (!img.mask.empty() && (img.mask.cols != c.width || img.mask.rows != c.height || img.mask.type() != CV_8U))
    throw bad_input("the mask of image {} is {}x{} (8-bit expected) but its camera is {}x{}", k, img.mask.cols,
                    img.mask.rows, c.width, c.height);
}

struct PendingSample {
  std::uint32_t lumitexel;
  Sample sample;
};

}  // namespace

HomeAssignment assign_home_images(const TriangleMesh& mesh, const std::vector<ImageView>& views, int threads) {
  HomeAssignment home;
  home.image.assign(mesh.triangles.size(), -1);
  home.pixels.assign(mesh.triangles.size(), 0);
  std::vector<std::size_t> first_image;
  distinct_cameras(views, first_image);
  for (std::size_t c = 0; c < first_image.size(); ++c) {
    const PinholeCamera& cam = views[first_image[c]].camera;
    const Fragments f = depth_only(mesh, cam, threads);
    const std::vector<std::uint32_t> covered = reflectance::projected_pixel_counts(mesh, cam);
    std::vector<std::uint32_t> visible(mesh.triangles.size(), 0);
    for (std::int32_t t : f.triangle)
      if (t >= 0) ++visible[static_cast<std::size_t>(t)];
    const Eigen::Vector3d eye = cam.centre();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (visible[t] == 0 || 2 * visible[t] < covered[t] || !front_facing(mesh, t, eye)) continue;
      if (visible[t] > home.pixels[t]) {  // strict: ties keep the earlier image
        home.pixels[t] = visible[t];
        home.image[t] = static_cast<std::int32_t>(first_image[c]);
      }
    }
  }
  return home;
}

LumitexelSet build_lumitexels(const TriangleMesh& mesh, const std::vector<ImageView>& views, const ImageLoader& load,
                              const LumitexelOptions& o, LumitexelReport* report) {
  LumitexelReport rep;
  if (views.size() > 65535) throw bad_input("{} images; the .ltx format indexes at most 65535", views.size());
  const double eps = o.depth_eps > 0 ? o.depth_eps : 0.002 * reflectance::bbox_diagonal(mesh);
  int shadow_res = o.shadow_resolution;
  if (shadow_res <= 0) {
    for (const ImageView& v : views) shadow_res = std::max({shadow_res, v.camera.width, v.camera.height});
    shadow_res = std::clamp(shadow_res, 512, 8192);
  }
  auto t0 = SteadyClock::now();
  const std::uint64_t steps = 1 + 2 * static_cast<std::uint64_t>(views.size());
  std::uint64_t step = 0;
  const auto advance = [&] {
    if (o.progress) o.progress(++step, steps);
  };

  // 1. Home images.
  const HomeAssignment home = assign_home_images(mesh, views, o.threads);
  advance();
  for (std::int32_t h : home.image) rep.triangles_with_home += h >= 0;
  rep.seconds.push_back(seconds_since(t0));
  t0 = SteadyClock::now();

  // 2. One lumitexel per home pixel, grouped by triangle.
  std::vector<Lumitexel> points;
  for (std::size_t k = 0; k < views.size(); ++k) {
    advance();
    bool is_home = false;
    for (std::int32_t h : home.image) is_home = is_home || h == static_cast<std::int32_t>(k);
    if (!is_home) continue;
    reflectance::RasterOptions ro;
    ro.threads = o.threads;
    const Fragments f = reflectance::rasterize(mesh, views[k].camera, ro);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        const std::size_t i = f.index(x, y);
        const std::int32_t t = f.triangle[i];
        if (t < 0 || home.image[static_cast<std::size_t>(t)] != static_cast<std::int32_t>(k)) continue;
        Lumitexel l;
        l.p = reflectance::fragment_point(mesh, f, i).cast<float>();
        l.n = reflectance::fragment_normal(mesh, f, i).cast<float>();
        l.triangle = static_cast<std::uint32_t>(t);
        l.home_image = static_cast<std::uint16_t>(k);
        l.home_pixel = Eigen::Vector2f(static_cast<float>(x), static_cast<float>(y));
        points.push_back(l);
      }
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const Lumitexel& a, const Lumitexel& b) { return a.triangle < b.triangle; });
  rep.candidates = points.size();
  if (points.size() > std::numeric_limits<std::uint32_t>::max()) throw bad_input("more than 2^32 lumitexels");
  rep.seconds.push_back(seconds_since(t0));
  t0 = SteadyClock::now();

  // 3. Samples, one image at a time; depth buffers per distinct camera are reused.
  std::vector<std::size_t> first_image;
  const std::vector<std::size_t> cam_of = distinct_cameras(views, first_image);
  std::vector<std::vector<float>> depth(first_image.size());
  std::vector<std::uint32_t> count(points.size(), 0);
  std::vector<std::vector<PendingSample>> per_image(views.size());
  for (std::size_t k = 0; k < views.size(); ++k) {
    const ImageView& view = views[k];
    const ImagePixels img = load(k);
    check_pixels(img, view, k);
    std::vector<float>& zbuf = depth[cam_of[k]];
    if (zbuf.empty()) zbuf = depth_only(mesh, view.camera, o.threads).depth;
    const reflectance::ShadowMap shadow =
        reflectance::make_shadow_map(mesh, view.light.position, shadow_res, eps, o.threads);
    const Eigen::Vector3d eye = view.camera.centre();
    const int bands = band_count(static_cast<int>(points.size()), o.threads);
    std::vector<std::vector<PendingSample>> band_out(static_cast<std::size_t>(bands));
    std::vector<LumitexelReport> band_rep(static_cast<std::size_t>(bands));
    // Bands are contiguous and concatenated in order: the result is thread-count independent.
    parallel_bands_indexed(static_cast<int>(points.size()), bands, [&](int band, int begin, int end) {
      auto& out = band_out[static_cast<std::size_t>(band)];
      auto& r = band_rep[static_cast<std::size_t>(band)];
      for (int i = begin; i < end; ++i) {
        const Lumitexel& l = points[static_cast<std::size_t>(i)];
        const Eigen::Vector3d p = l.p.cast<double>(), n = l.n.cast<double>();
        const Eigen::Vector3d xc = view.camera.to_camera(p);
        if (xc.z() <= 0) {
          ++r.rejected_mask;
          continue;
        }
        const Eigen::Vector2d ideal = view.camera.project_camera(xc);
        const int px = static_cast<int>(std::lround(ideal.x())), py = static_cast<int>(std::lround(ideal.y()));
        if (px < 0 || py < 0 || px >= view.camera.width || py >= view.camera.height) {
          ++r.rejected_mask;
          continue;
        }
        if (xc.z() > zbuf[static_cast<std::size_t>(py) * view.camera.width + px] + eps) {
          ++r.rejected_occluded;
          continue;
        }
        const Eigen::Vector3d to_light = view.light.position - p;
        const double d2 = to_light.squaredNorm();
        const Eigen::Vector3d u = to_light / std::sqrt(d2), v = (eye - p).normalized();
        if (u.dot(n) <= o.min_cos || v.dot(n) <= o.min_cos) {
          ++r.rejected_grazing;
          continue;
        }
        if (!shadow.lit(p)) {
          ++r.rejected_shadowed;
          continue;
        }
        Eigen::Vector3d L;
        bool nonfinite = false;
        if (!resample(img, view.camera.project_distorted(p), L, nonfinite)) {
          ++r.rejected_mask;
          r.nonfinite_pixels += nonfinite;
          continue;
        }
        Sample s;
        s.image = static_cast<std::uint16_t>(k);
        s.u_world = u.cast<float>();
        s.v_world = v.cast<float>();
        s.r = (L * d2).cwiseQuotient(view.light.intensity).cast<float>();
        out.push_back({static_cast<std::uint32_t>(i), s});
      }
    });
    for (std::size_t b = 0; b < band_out.size(); ++b) {
      per_image[k].insert(per_image[k].end(), band_out[b].begin(), band_out[b].end());
      rep.rejected_mask += band_rep[b].rejected_mask;
      rep.rejected_occluded += band_rep[b].rejected_occluded;
      rep.rejected_grazing += band_rep[b].rejected_grazing;
      rep.rejected_shadowed += band_rep[b].rejected_shadowed;
      rep.nonfinite_pixels += band_rep[b].nonfinite_pixels;
    }
    for (const PendingSample& ps : per_image[k]) ++count[ps.lumitexel];
    advance();
  }

  // 4. Keep lumitexels with enough samples; samples grouped per lumitexel, images in order.
  LumitexelSet set;
  std::vector<std::int64_t> new_index(points.size(), -1);
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (count[i] < static_cast<std::uint32_t>(std::max(1, o.min_samples)) || count[i] > 65535) {
      ++rep.dropped;
      continue;
    }
    new_index[i] = static_cast<std::int64_t>(set.lumitexels.size());
    Lumitexel l = points[i];
    l.first_sample = total;
    l.count = static_cast<std::uint16_t>(count[i]);
    total += count[i];
    set.lumitexels.push_back(l);
  }
  if (set.lumitexels.empty())
    throw bad_input("no lumitexel has >= {} samples ({} candidate points, {} images)", o.min_samples,
                          points.size(), views.size());
  set.samples.resize(total);
  std::vector<std::uint64_t> fill(set.lumitexels.size(), 0);
  for (std::size_t k = 0; k < views.size(); ++k) {
    for (const PendingSample& ps : per_image[k]) {
      const std::int64_t j = new_index[ps.lumitexel];
      if (j < 0) continue;
      Lumitexel& l = set.lumitexels[static_cast<std::size_t>(j)];
      set.samples[l.first_sample + fill[static_cast<std::size_t>(j)]++] = ps.sample;
    }
    std::vector<PendingSample>().swap(per_image[k]);
  }
  rep.samples = set.samples.size();
  rep.seconds.push_back(seconds_since(t0));
  if (report) *report = rep;
  return set;
}

}  // namespace fest::brdffit
