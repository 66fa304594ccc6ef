#pragma once
// The ray caster (docs/volrender.md "Sampling", "Modes", "Acceleration"): rays in index
// space clipped exactly to the sample box, segments of length step (voxel units = the
// smallest spacing) with one midpoint sample each, weighted by their true length, so the
// integral covers [t_entry, t_exit] whatever the step. Front-to-back emission-absorption
// with opacity correction, optional Blinn-Phong shading and pre-integration; MIP, MinIP,
// average; shaded semi-transparent isosurfaces. Empty-space skipping over the min-max
// pyramid's nodes (its finest level and up to 5 coarser) and early ray termination never
// change a pixel's bytes.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "core/progress_callback.hpp"
#include "raycast/camera.hpp"
#include "raycast/transfer_function.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::raycast {

enum class Mode { dvr, mip, minip, avg, iso, slices };

struct IsoLayer {
  double value = 0;
  double alpha = 1;
  std::optional<std::array<double, 3>> color;  // default: the transfer function's colour at value
};

// The chapter's stacked slice planes with iso-contour bands (fig. 4.5b): planes
// {x : normal . x = offset} (world units), contour levels c0 + j dc, j < count.
struct SliceStack {
  Vec3 normal{0, 0, 1};
  std::vector<double> offsets;
  double c0 = 0, dc = 1;
  int count = 0;
  double width = 1;          // contour band width, data units
  double width_world = 0;    // > 0: band width width_world * |grad f| (world units: lines of constant width)
  double frame_width = 0;    // > 0: the plane's outline on the volume box, this wide (world units), in white
  double contour_alpha = 1;
  double tf_unit = 1;        // a plane takes the TF opacity a(v) of one tf_unit layer
};

struct RenderOptions {
  Mode mode = Mode::dvr;
  double step = 0.5;            // voxel units
  bool jitter = false;
  bool nearest = false;         // nearest-neighbour reconstruction instead of trilinear
  bool shade = false;
  std::array<double, 4> phong{0.3, 0.7, 0.2, 20};  // ka, kd, ks, exponent
  bool two_sided = false;
  double ert = 0.995;           // early ray termination threshold on accumulated opacity
  bool preint = false;
  std::array<double, 3> background{0, 0, 0};
  bool keep_alpha = false;      // --bg none: colour un-premultiplied, alpha kept
  std::optional<std::array<double, 2>> window;  // mip/minip/avg: grey window instead of TF colour
  std::vector<IsoLayer> isos;
  SliceStack slices;
  int spp = 1;                  // 1, 4, 9 or 16 stratified sub-pixel rays
  int threads = 1;
  bool skip_empty = true;
  // Central-difference gradients precomputed at every sample and interpolated, instead of
  // 48 reads per shaded sample; the same values up to rounding. render() builds them when
  // the caller passes no ShadingVolume.
  bool gradient_cache = false;
  // The pixels to cast, width x height, row 0 at the top: 0 = not cast, left at the
  // background (transparent with keep_alpha) at infinite depth (the part of a showcase
  // screen another viewer's mirror covers); empty = every pixel.
  std::vector<std::uint8_t> pixel_mask;
  ProgressFn progress;  // render(): image tiles cast of all, on the calling thread
};

// The value and the central-difference gradient (index space) of every sample, interleaved
// as {f, df/di, df/dj, df/dk} (16 bytes per voxel), so that one cache line per corner serves
// both the trilinear value and the interpolated gradient of a shaded sample (docs/volrender.md
// "Acceleration"). Built once per volume and shared by every image rendered from it.
// Integer data (CT, most MR) whose values and doubled differences fit 16 bits are stored
// exactly in half the bytes instead: {f, 2 df/di, 2 df/dj, 2 df/dk} as int16 (a central
// difference of integers is a multiple of 1/2), the same numbers, the same images.
struct ShadingVolume {
  struct Free {
    template <typename T>
    void operator()(T* p) const noexcept { std::free(p); }
  };
  // On 2 MiB-aligned memory offered to the kernel as huge pages (a ray crossing z planes
  // touches a new 4 KiB page every step); filled in parallel, first touch. One of the two.
  std::unique_ptr<float[], Free> data;            // 4 floats per sample, x fastest
  std::unique_ptr<std::int16_t[], Free> data16;   // 4 int16 per sample, x fastest
  std::size_t samples = 0;
  bool built() const noexcept { return data || data16; }
};
ShadingVolume shading_volume(const volume_pyramid::ScalarGrid& grid, int threads);

struct RenderStats {
  std::size_t rays = 0, samples = 0, skipped = 0, terminated = 0;
};

struct RenderedImage {
  int width = 0, height = 0;
  std::vector<float> rgba;   // linear, straight colour when keep_alpha, else alpha = coverage
  std::vector<float> depth;  // world distance from the ray origin; +inf where none
  RenderStats stats;
};

// An opaque surface a ray stops at (volrender --mesh): per ray, the ray parameter t of the
// first hit and its colour (already shaded); t = +inf where none. Supplied by the caller.
struct SurfaceHit {
  double t = INFINITY;
  std::array<double, 3> rgb{0, 0, 0};
};
using SurfaceTracer = SurfaceHit (*)(const void* context, const Ray& ray);

// `pyramid` may be null (no skipping); its finest level sets the skipping block size (2^l
// cells; volrender builds level 2, 4^3 cells), coarser levels skip larger empty regions at
// once. `shading` (with gradient_cache) must come from shading_volume(grid); null: render()
// builds one. Throws std::invalid_argument for bad options.
RenderedImage render(const volume_pyramid::ScalarGrid& grid, const volume_pyramid::MinMaxPyramid* pyramid,
                     const TransferFunction& tf, const Camera& camera, const RenderOptions& options,
                     SurfaceTracer surface = nullptr, const void* surface_context = nullptr,
                     const ShadingVolume* shading = nullptr);

// Slab-method clipping of a world ray to the grid's sample box; returns false when the ray
// misses. t0/t1 are the ray parameters of entry and exit (t0 may be negative for an
// origin inside).
bool clip_to_grid(const volume_pyramid::ScalarGrid& grid, const Ray& ray, double& t0, double& t1);

// Trilinear sample at continuous index position (clamped to the box).
double sample_trilinear(const volume_pyramid::ScalarGrid& grid, double x, double y, double z);

}  // namespace fest::raycast
