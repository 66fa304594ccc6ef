// Synthetic head: shapes are defined in mm around the grid centre.
#include "segbrain/phantom.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace fest::segbrain {
namespace {

// Normalised ellipsoid radius: < 1 inside.
double ell(double x, double y, double z, double a, double b, double c) {
  return std::sqrt((x / a) * (x / a) + (y / b) * (y / b) + (z / c) * (z / c));
}

// Distance from p to the segment s.
double segment_distance(const std::array<double, 3>& p, const NerveSegment& s) {
  double d[3], u[3], dd = 0, du = 0;
  for (int a = 0; a < 3; ++a) {
    d[a] = s.to[a] - s.from[a];
    u[a] = p[a] - s.from[a];
    dd += d[a] * d[a];
    du += d[a] * u[a];
  }
  const double t = std::clamp(du / dd, 0.0, 1.0);
  double r2 = 0;
  for (int a = 0; a < 3; ++a) r2 += (u[a] - t * d[a]) * (u[a] - t * d[a]);
  return std::sqrt(r2);
}

}  // namespace

// The head's centre lies 5 mm above the grid centre; the eyes 30 mm below it, 70 mm in
// front and 32 mm either side.
std::array<std::array<double, 3>, 2> phantom_eye_centres() { return {{{-32, 70, -25}, {32, 70, -25}}}; }

// From the posterior pole of each globe back, medially and 10 mm up to a chiasm 50 mm
// behind the eye centres (as on Colin27: about 50 mm behind, 10-15 mm above).
std::array<NerveSegment, 2> phantom_nerves() {
  auto eyes = phantom_eye_centres();
  std::array<NerveSegment, 2> out;
  for (int s = 0; s < 2; ++s)
    out[s] = {{eyes[s][0], eyes[s][1] - kEyeRadiusMm, eyes[s][2]}, {0, eyes[s][1] - 50, eyes[s][2] + 10}};
  return out;
}

Phantom make_phantom(const PhantomOptions& o) {
  for (int a = 0; a < 3; ++a)
    if (o.size[a] < 8 || o.spacing[a] <= 0) throw bad_input("phantom grid must be >= 8 voxels with positive spacing");
  Phantom p;
  p.grid.n = o.size;
  p.grid.spacing = o.spacing;
  const Grid& g = p.grid;
  p.t1.assign(g.size(), 0);
  p.truth.assign(g.size(), 0);
  const double WM = 110, GM = 80, CSF = 30, FAT = 180, BONE = 20, MUSCLE = 60, NERVE = 100;
  SplitMix64 rng{o.seed * 7919 + 17};  // SplitMix64 and Box-Muller: the same noise everywhere
  const auto nerves = phantom_nerves();
  for (std::size_t k = 0; k < g.n[2]; ++k)
    for (std::size_t j = 0; j < g.n[1]; ++j)
      for (std::size_t i = 0; i < g.n[0]; ++i) {
        double x = (i - 0.5 * (g.n[0] - 1)) * g.spacing[0];
        double y = (j - 0.5 * (g.n[1] - 1)) * g.spacing[1];
        double z = (k - 0.5 * (g.n[2] - 1)) * g.spacing[2];
        double hz = z - 5;                           // head centre 5 mm above the grid centre
        double rh = ell(x, y, hz, 72, 90, 70);       // outer scalp
        // Brain surface with sulci: a cosine-modulated ellipsoid (radius ±4 %).
        double th = std::atan2(y, x), ph = std::atan2(hz, std::hypot(x, y));
        double rb = ell(x, y, hz, 58, 76, 56) / (1 + 0.04 * std::cos(9 * th) * std::cos(7 * ph));
        double rwm = ell(x, y, hz, 52, 70, 50);
        double rskull_in = ell(x, y, hz, 62, 80, 60);
        double rskull_out = ell(x, y, hz, 68, 86, 66);
        bool neck = hz < -20 && std::hypot(x, (y + 10) * 0.9) < 45;
        double v = 0;
        int lab = 0;
        // Eyes: vitreous balls (r 12 mm) in orbital fat, in front of the brain.
        bool eye = false, orbit = false;
        for (const auto& c : phantom_eye_centres()) {
          double d = std::sqrt((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]));
          eye = eye || d < kEyeRadiusMm;
          orbit = orbit || d < 16;
        }
        if (rh < 1 || neck) {
          lab = 1;
          v = neck && rh >= 1 ? MUSCLE : FAT;
          if (rh < 1 && neck && ell(x, y, hz, 66, 84, 64) < 1) v = MUSCLE;
          if (rskull_out < 1) v = BONE;
          if (rskull_in < 1) {
            v = CSF;
            lab = 2;
          }
          if (rb < 1) {
            v = rwm < 1 ? WM : GM;
            lab = 3;
            for (int s : {-1, 1})
              if (ell(x - s * 10, y + 5, hz - 8, 6, 22, 9) < 1) {
                v = CSF;
                lab = 6;
              }
          }
          if (orbit && lab <= 1) v = FAT;
          if (eye && lab <= 1) {
            v = CSF;
            lab = 10;
          }
        }
        if (!eye && lab != 6) {
          const std::array<double, 3> at{x, y, z};
          const double dn = std::min(segment_distance(at, nerves[0]), segment_distance(at, nerves[1]));
          if (dn <= kNerveRadiusMm) {
            v = NERVE;
            lab = 9;
          } else if (dn <= 2 * kNerveRadiusMm && (lab == 2 || lab == 3)) {
            v = CSF;  // the dural sheath's CSF inside the skull
            lab = 2;
          }
        }
        // Low-order polynomial bias field, 1 ± bias/2 across the head.
        double b = 1 + 0.5 * o.bias * (0.6 * x / 80 + 0.3 * y / 96 - 0.4 * (z / 80) * (z / 80) + 0.2);
        v *= b;
        const double sd = o.noise * WM;
        double n1 = rng.normal() * sd, n2 = rng.normal() * sd;
        std::size_t idx = g.index(i, j, k);
        p.t1[idx] = static_cast<float>(std::sqrt((v + n1) * (v + n1) + n2 * n2));  // Rician magnitude
        p.truth[idx] = static_cast<std::uint8_t>(lab);
      }
  return p;
}

}  // namespace fest::segbrain
