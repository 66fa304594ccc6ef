#include "sampling/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "sampling/kernel_params.hpp"
#include "sampling/resize.hpp"
#include "sampling/sample_patterns.hpp"

namespace fest::sampling {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double sigma_p = 0.5;  // screen-pixel Gaussian prefilter (pixels)
constexpr double sigma_r = 0.5;  // texel reconstruction (texels)

template <typename Body>
void for_rows(int rows, int threads, Body body) {
  const int n = std::max(1, std::min(resolve_threads(threads), rows));
  if (n == 1) {
    for (int y = 0; y < rows; ++y) body(y);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < n; ++t)
    pool.emplace_back([&, t] {
      for (int y = t; y < rows; y += n) body(y);  // interleaved: far rows cost more
    });
  for (auto& th : pool) th.join();
}

int wrap(long i, int n) { return static_cast<int>(((i % n) + n) % n); }

// Bilinear lookup of channel 0 at level-texel coordinates (centres at i + ½), wrapping.
double bilinear(const FloatImage& img, double u, double v) {
  const double x = u - 0.5, y = v - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const long x0 = static_cast<long>(fx), y0 = static_cast<long>(fy);
  const int c = img.channels;
  auto at = [&](long i, long j) { return static_cast<double>(img.row(wrap(j, img.height))[wrap(i, img.width) * c]); };
  return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) + ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1));
}

// Level-0 coordinates to level ℓ (sizes may be odd: scale by the actual size ratio).
double level_bilinear(const MipPyramid& p, int l, double u, double v) {
  const FloatImage& t = p.levels[static_cast<std::size_t>(l)];
  const FloatImage& t0 = p.levels[0];
  return bilinear(t, u * t.width / t0.width, v * t.height / t0.height);
}

double trilinear_at(const MipPyramid& p, double lambda, double u, double v) {
  const int top = static_cast<int>(p.levels.size()) - 1;
  lambda = std::clamp(lambda, 0.0, static_cast<double>(top));
  const int l0 = static_cast<int>(std::floor(lambda)), l1 = std::min(top, l0 + 1);
  const double f = lambda - l0;
  const double a = level_bilinear(p, l0, u, v);
  return f > 0 ? (1 - f) * a + f * level_bilinear(p, l1, u, v) : a;
}

double ewa_at_level(const MipPyramid& p, int l, double u, double v, const double cov[3]) {
  const FloatImage& t = p.levels[static_cast<std::size_t>(l)];
  const FloatImage& t0 = p.levels[0];
  const double sx = static_cast<double>(t.width) / t0.width, sy = static_cast<double>(t.height) / t0.height;
  // Σ_ℓ = S Σ S with S = diag(sx, sy) (= Σ / 4^ℓ for power-of-two sizes).
  const double a = cov[0] * sx * sx, b = cov[1] * sx * sy, d = cov[2] * sy * sy;
  const double det = a * d - b * b;
  const double ia = d / det, ib = -b / det, id = a / det;
  const double ul = u * sx, vl = v * sy;
  const double ru = 3 * std::sqrt(a), rv = 3 * std::sqrt(d);  // bounding box of dᵀΣ⁻¹d ≤ 9
  const long i0 = static_cast<long>(std::floor(ul - ru - 0.5)), i1 = static_cast<long>(std::ceil(ul + ru - 0.5));
  const long j0 = static_cast<long>(std::floor(vl - rv - 0.5)), j1 = static_cast<long>(std::ceil(vl + rv - 0.5));
  double sum = 0, wsum = 0;
  for (long j = j0; j <= j1; ++j) {
    const double dv = j + 0.5 - vl;
    const float* row = t.row(wrap(j, t.height));
    for (long i = i0; i <= i1; ++i) {
      const double du = i + 0.5 - ul;
      const double q = ia * du * du + 2 * ib * du * dv + id * dv * dv;
      if (q > 9) continue;
      const double w = std::exp(-0.5 * q);
      sum += w * row[static_cast<std::size_t>(wrap(i, t.width)) * static_cast<std::size_t>(t.channels)];
      wsum += w;
    }
  }
  return wsum > 0 ? sum / wsum : level_bilinear(p, l, u, v);
}

struct Jacobian {
  double ux, uy, vx, vy;
  bool ok = false;
};

Jacobian jacobian(const TextureMap& map, double x, double y) {
  constexpr double e = 0.05;
  const TexCoord l = map(x - e, y), r = map(x + e, y), t = map(x, y - e), b = map(x, y + e);
  Jacobian j;
  if (!(l.visible && r.visible && t.visible && b.visible)) return j;
  j.ux = (r.u - l.u) / (2 * e);
  j.vx = (r.v - l.v) / (2 * e);
  j.uy = (b.u - t.u) / (2 * e);
  j.vy = (b.v - t.v) / (2 * e);
  j.ok = true;
  return j;
}

double lookup(const MipPyramid& p, const TexCoord& c, const Jacobian& j, const TextureOptions& o) {
  switch (o.method) {
    case TexMethod::nearest: {
      const FloatImage& t = p.levels[0];
      return t.row(wrap(static_cast<long>(std::floor(c.v)), t.height))[wrap(static_cast<long>(std::floor(c.u)), t.width) * t.channels];
    }
    case TexMethod::bilinear:
      return bilinear(p.levels[0], c.u, c.v);
    case TexMethod::trilinear: {
      const double rho = std::max(std::hypot(j.ux, j.vx), std::hypot(j.uy, j.vy));
      return trilinear_at(p, std::log2(std::max(rho, 1e-12)) + o.lod_bias, c.u, c.v);
    }
    case TexMethod::aniso: {
      const double lx = std::hypot(j.ux, j.vx), ly = std::hypot(j.uy, j.vy);
      const bool x_major = lx >= ly;
      const double pmax = std::max(lx, ly), pmin = std::max(std::min(lx, ly), 1e-12);
      const int n = std::max(1, std::min(static_cast<int>(std::ceil(pmax / pmin)), o.max_aniso));
      const double lambda = std::log2(std::max(pmax / n, 1e-12)) + o.lod_bias;
      const double mu = x_major ? j.ux : j.uy, mv = x_major ? j.vx : j.vy;
      double sum = 0, wsum = 0;
      for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n - 0.5;
        const double w = o.aniso_gauss ? std::exp(-t * t / (2 * 0.25 * 0.25)) : 1.0;
        sum += w * trilinear_at(p, lambda, c.u + t * mu, c.v + t * mv);
        wsum += w;
      }
      return sum / wsum;
    }
    case TexMethod::ewa: {
      // Σ = σp² J Jᵀ + σr² I, its minor axis raised so the anisotropy is at most maxaniso.
      double a = sigma_p * sigma_p * (j.ux * j.ux + j.uy * j.uy) + sigma_r * sigma_r;
      double b = sigma_p * sigma_p * (j.ux * j.vx + j.uy * j.vy);
      double d = sigma_p * sigma_p * (j.vx * j.vx + j.vy * j.vy) + sigma_r * sigma_r;
      const double tr = a + d, disc = std::sqrt(std::max(0.0, (a - d) * (a - d) / 4 + b * b));
      const double l1 = tr / 2 + disc;
      double l2 = tr / 2 - disc;
      const double limit = l1 / (static_cast<double>(o.max_aniso) * o.max_aniso);
      if (l2 < limit) {
        // Σ' = Σ + (limit − l2) e₂e₂ᵀ, e₂ the minor eigenvector.
        double ex = b, ey = l2 - a;
        if (std::hypot(ex, ey) < 1e-300) ex = (a <= d) ? 1 : 0, ey = (a <= d) ? 0 : 1;
        const double len = std::hypot(ex, ey);
        ex /= len;
        ey /= len;
        const double add = limit - l2;
        a += add * ex * ex;
        b += add * ex * ey;
        d += add * ey * ey;
        l2 = limit;
      }
      const double cov[3] = {a, b, d};
      const int top = static_cast<int>(p.levels.size()) - 1;
      const double level = std::clamp(std::log2(std::sqrt(l2)) + o.lod_bias, 0.0, static_cast<double>(top));
      const int lo = static_cast<int>(std::floor(level)), hi = std::min(top, lo + 1);
      const double f = level - lo;
      const double v0 = ewa_at_level(p, lo, c.u, c.v, cov);
      return f > 0 ? (1 - f) * v0 + f * ewa_at_level(p, hi, c.u, c.v, cov) : v0;
    }
  }
  return 0;
}

}  // namespace

const char* pyramid_kernel(PyramidFilter filter) {
  switch (filter) {
    case PyramidFilter::gaussian: return "gaussian:sigma=0.5";
    case PyramidFilter::lanczos3: return "lanczos3";
    case PyramidFilter::box: break;
  }
  return "box";
}

MipPyramid build_pyramid(const FloatImage& texture, PyramidFilter filter, int threads) {
  ResizeOptions o;
  o.kernel = make_kernel(pyramid_kernel(filter));
  o.edge = EdgeMode::wrap;
  o.clamp = ClampMode::none;
  o.threads = threads;
  MipPyramid p;
  p.levels.push_back(texture);
  while (p.levels.back().width > 1 || p.levels.back().height > 1) {
    const FloatImage& l = p.levels.back();
    p.levels.push_back(resize_working(l, std::max(1, l.width / 2), std::max(1, l.height / 2), o));
  }
  return p;
}

TextureMap plane_map(double h, double pitch, double fov, double period, int width, int height, int tw, int th) {
  if (!(h > 0) || !(fov > 0 && fov < 180) || !(period > 0) || !std::isfinite(pitch) || std::fabs(pitch) >= 90)
    throw usage_error("plane view: need h > 0, |pitch| < 90, 0 < fov < 180, period > 0");
  const double tan_half = std::tan(fov * pi / 360), aspect = static_cast<double>(width) / height;
  const double cp = std::cos(pitch * pi / 180), sp = std::sin(pitch * pi / 180);
  return [=](double x, double y) {
    const double sx = (2 * x / width - 1) * tan_half * aspect, sy = (1 - 2 * y / height) * tan_half;
    // Camera: right = (1, 0, 0), forward = (0, cos p, −sin p), up = (0, sin p, cos p).
    const double dx = sx, dy = cp + sy * sp, dz = -sp + sy * cp;
    TexCoord c;
    if (dz >= -1e-9) return c;  // at or above the horizon
    const double t = h / -dz;
    c.u = t * dx / period * tw;
    c.v = t * dy / period * th;
    c.visible = true;
    return c;
  };
}

TextureMap table_map(const FloatImage& uv, int tw, int th) {
  if (uv.channels != 2) throw bad_input("texture coordinates need 2 channels (u, v), got {}", uv.channels);
  return [&uv, tw, th](double x, double y) {
    const double px = std::clamp(x - 0.5, 0.0, uv.width - 1.0), py = std::clamp(y - 0.5, 0.0, uv.height - 1.0);
    const int x0 = std::min(static_cast<int>(px), uv.width - 1), y0 = std::min(static_cast<int>(py), uv.height - 1);
    const int x1 = std::min(x0 + 1, uv.width - 1), y1 = std::min(y0 + 1, uv.height - 1);
    const double fx = px - x0, fy = py - y0;
    auto get = [&](int i, int j, int ch) { return static_cast<double>(uv.row(j)[i * 2 + ch]); };
    auto lerp = [&](int ch) {
      return (1 - fy) * ((1 - fx) * get(x0, y0, ch) + fx * get(x1, y0, ch)) + fy * ((1 - fx) * get(x0, y1, ch) + fx * get(x1, y1, ch));
    };
    TexCoord c;
    c.u = lerp(0) * tw;
    c.v = lerp(1) * th;
    c.visible = true;
    return c;
  };
}

TextureOptions parse_texture_method(const std::string& spec) {
  TextureOptions o;
  const KernelSpelling s = split_kernel_spelling(spec);
  if (s.name == "nearest" || s.name == "bilinear" || s.name == "trilinear") {
    if (!s.rest.empty()) throw usage_error("texture method: {} takes no parameters", s.name);
    o.method = s.name == "nearest" ? TexMethod::nearest : s.name == "bilinear" ? TexMethod::bilinear : TexMethod::trilinear;
    return o;
  }
  if (s.name == "aniso") {
    o.method = TexMethod::aniso;
    std::string n = s.rest;
    const auto colon = n.find(':');
    if (colon != std::string::npos) {
      if (n.substr(colon + 1) != "gauss") throw usage_error("texture method: aniso:N[:gauss], got '{}'", spec);
      o.aniso_gauss = true;
      n = n.substr(0, colon);
    }
    char* end = nullptr;
    const long v = std::strtol(n.c_str(), &end, 10);
    if (n.empty() || *end != '\0' || v < 1 || v > 64) throw usage_error("texture method: aniso:N needs N in [1, 64], got '{}'", spec);
    o.max_aniso = static_cast<int>(v);
    return o;
  }
  if (s.name == "ewa") {
    o.method = TexMethod::ewa;
    const auto p = parse_kernel_params("ewa", s.rest, {{"maxaniso", 16}});
    if (!(p.at("maxaniso") >= 1 && p.at("maxaniso") <= 64)) throw usage_error("ewa: maxaniso must be in [1, 64]");
    o.max_aniso = static_cast<int>(p.at("maxaniso"));
    return o;
  }
  throw usage_error("unknown texture method '{}' (nearest, bilinear, trilinear, aniso:N, ewa[:maxaniso=16])", spec);
}

FloatImage texture_screen(const MipPyramid& pyr, const TextureMap& map, int width, int height, const TextureOptions& o) {
  FloatImage out(width, height, 1);
  for_rows(height, o.threads, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      const TexCoord c = map(cx, cy);
      const Jacobian j = jacobian(map, cx, cy);
      out.row(y)[x] = (c.visible && j.ok) ? static_cast<float>(lookup(pyr, c, j, o)) : 0.5f;
    }
  });
  return out;
}

FloatImage texture_ground_truth(const FloatImage& texture, const TextureMap& map, int width, int height, std::uint64_t seed,
                                int threads) {
  FloatImage out(width, height, 1);
  for_rows(height, threads, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      const Jacobian j = jacobian(map, cx, cy);
      const double area = j.ok ? std::fabs(j.ux * j.vy - j.uy * j.vx) * 9 : 0;  // texels under the 3σ window
      const int n = static_cast<int>(std::ceil(std::sqrt(std::clamp(4 * area, 1024.0, 65536.0))));
      const auto s = pixel_samples(Pattern::jitter, n * n, seed, x, y);
      double sum = 0, wsum = 0;
      for (const Point2& p : s) {
        const double dx = (p.x - 0.5) * 6 * sigma_p, dy = (p.y - 0.5) * 6 * sigma_p;
        const double w = std::exp(-(dx * dx + dy * dy) / (2 * sigma_p * sigma_p));
        const TexCoord c = map(cx + dx, cy + dy);
        sum += w * (c.visible ? bilinear(texture, c.u, c.v) : 0.5);
        wsum += w;
      }
      out.row(y)[x] = static_cast<float>(sum / wsum);
    }
  });
  return out;
}

FloatImage footprint_anisotropy(const TextureMap& map, int width, int height) {
  FloatImage out(width, height, 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Jacobian j = jacobian(map, x + 0.5, y + 0.5);
      if (!j.ok) continue;
      // Singular values of J: the footprint's major and minor axes.
      const double a = j.ux * j.ux + j.vx * j.vx, b = j.ux * j.uy + j.vx * j.vy, d = j.uy * j.uy + j.vy * j.vy;
      const double disc = std::sqrt(std::max(0.0, (a - d) * (a - d) / 4 + b * b));
      const double l1 = (a + d) / 2 + disc, l2 = std::max((a + d) / 2 - disc, 1e-300);
      out.row(y)[x] = static_cast<float>(std::sqrt(l1 / l2));
    }
  return out;
}

}  // namespace fest::sampling
