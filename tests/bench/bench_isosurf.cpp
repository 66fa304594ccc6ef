// isosurf exact against VTK 9.1's vtkMarchingCubes and vtkFlyingEdges3D in the same run
// (docs/isosurf.md "Performance"). One JSON line per case: triangles, vertices, seconds
// (best of 3, extraction only, read excluded), area/volume/closed for ours.
//
//   bench_isosurf [cranium.nrrd]     (default: $FEST_TESTDATA/volumes/cranium.nrrd)
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMarchingCubes.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"
#include "isosurface/adaptive.hpp"
#include "isosurface/marching_cubes.hpp"
#include "isosurface/mesh_stats.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

using namespace fest;
using Clock = std::chrono::steady_clock;

namespace {

double best_of(int n, const std::function<void()>& f) {
  double best = 1e30;
  for (int k = 0; k < n; ++k) {
    const auto t = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t).count());
  }
  return best;
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

vtkSmartPointer<vtkImageData> to_vtk(const volume_pyramid::ScalarGrid& g) {
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(int(g.dims[0]), int(g.dims[1]), int(g.dims[2]));
  img->SetSpacing(g.axes[0], g.axes[4], g.axes[8]);
  img->SetOrigin(g.origin[0], g.origin[1], g.origin[2]);
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetNumberOfTuples(vtkIdType(g.size()));
  std::copy(g.values.begin(), g.values.end(), a->GetPointer(0));
  img->GetPointData()->SetScalars(a);
  return img;
}

void run_adaptive(const std::string& name, const volume_pyramid::ScalarGrid& g, float iso, isosurface::AdaptiveOptions o,
                  std::size_t exact_triangles) {
  const volume_pyramid::MinMaxPyramid pyr(g, 1);
  isosurface::AdaptiveResult r;
  o.threads = 1;
  const double t = best_of(3, [&] { r = isosurface::extract_adaptive(g, iso, o, pyr); });
  const auto m = isosurface::mesh_stats(r.surface);
  nlohmann::json j = {{"case", name}, {"method", "isosurf adaptive"}, {"threads", 1}, {"seconds", t},
                      {"vertices", r.surface.vertices()}, {"triangles", r.surface.triangles.size()},
                      {"reduction_vs_exact", double(exact_triangles) / double(std::max<std::size_t>(1, r.surface.triangles.size()))},
                      {"closed", m.closed}, {"euler", m.euler}, {"leaves_per_level", r.leaves_per_level},
                      {"closure_splits", r.closure_splits}, {"peak_rss_mb", peak_rss_mb()}};
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
}

void run_case(const std::string& name, const volume_pyramid::ScalarGrid& g, float iso) {
  auto line = [&](const char* method, int threads, double s, std::size_t v, std::size_t t, nlohmann::json extra) {
    nlohmann::json j = {{"case", name}, {"method", method}, {"threads", threads}, {"seconds", s}, {"vertices", v}, {"triangles", t},
                        {"samples", g.size()}, {"peak_rss_mb", peak_rss_mb()}};
    j.update(extra);
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
  };
  volume_pyramid::MinMaxPyramid pyr;
  const double t_build = best_of(3, [&] { pyr = volume_pyramid::MinMaxPyramid(g, 1); });
  for (int threads : {1, 2}) {
    isosurface::ExtractOptions o;
    o.threads = threads;
    isosurface::Surface s;
    const double t = best_of(3, [&] { s = isosurface::extract_isosurface(g, iso, o, &pyr); });
    const auto m = isosurface::mesh_stats(s);
    line("isosurf exact (octree)", threads, t, s.vertices(), s.triangles.size(),
         {{"octree_build_s", t_build}, {"area", m.area}, {"volume", m.volume}, {"closed", m.closed}, {"euler", m.euler},
          {"mesh_mb", (s.xyz.size() * 4 + s.triangles.size() * 12) / 1048576.0}});
  }
  {
    isosurface::ExtractOptions o;
    isosurface::Surface s;
    const double t = best_of(3, [&] { s = isosurface::extract_isosurface(g, iso, o, nullptr); });
    line("isosurf exact (scan)", 1, t, s.vertices(), s.triangles.size(), nlohmann::json::object());
  }
  auto img = to_vtk(g);
  {
    vtkSMPTools::Initialize(1);
    auto mc = vtkSmartPointer<vtkMarchingCubes>::New();
    mc->SetInputData(img);
    mc->SetValue(0, iso);
    mc->ComputeNormalsOff(), mc->ComputeGradientsOff(), mc->ComputeScalarsOff();
    const double t = best_of(3, [&] { mc->Modified(); mc->Update(); });
    line("vtkMarchingCubes", 1, t, std::size_t(mc->GetOutput()->GetNumberOfPoints()), std::size_t(mc->GetOutput()->GetNumberOfPolys()), nlohmann::json::object());
  }
  for (int threads : {1, 2}) {
    vtkSMPTools::Initialize(threads);
    auto fe = vtkSmartPointer<vtkFlyingEdges3D>::New();
    fe->SetInputData(img);
    fe->SetValue(0, iso);
    fe->ComputeNormalsOff(), fe->ComputeGradientsOff(), fe->ComputeScalarsOff();
    const double t = best_of(3, [&] { fe->Modified(); fe->Update(); });
    line("vtkFlyingEdges3D", threads, t, std::size_t(fe->GetOutput()->GetNumberOfPoints()), std::size_t(fe->GetOutput()->GetNumberOfPolys()), nlohmann::json::object());
  }
}

volume_pyramid::ScalarGrid sphere(std::size_t n, double R, double c, std::size_t corner = 0) {
  volume_pyramid::ScalarGrid g;
  g.dims = {n, n, n};
  g.values.resize(g.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i)
        g.values[g.index(i, j, k)] = static_cast<float>(
            std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c)) - R);
  (void)corner;
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  std::string ct = argc > 1 ? argv[1] : "";
  if (ct.empty()) {
    const char* d = std::getenv("FEST_TESTDATA");
    ct = std::string(d ? d : (std::string(std::getenv("HOME")) + "/.cache/fest/testdata")) + "/volumes/cranium.nrrd";
  }
  try {
    const auto in = formats::load_input(ct);
    std::size_t nans = 0;
    auto g = volume_pyramid::to_grid(formats::read_volume_source(in, {}), nans);
    const auto padded = volume_pyramid::padded(g, -1024.0f);
    run_case("cranium bone iso 225.5 cap -1024", padded, 225.5f);
    isosurface::AdaptiveOptions o;
    o.focus = std::array<double, 3>{122.0, 122.0, 80.25};
    o.focus_radius = 16;
    o.max_error = INFINITY;
    run_adaptive("cranium bone, focus at the centre, r0 16 mm, eps inf", padded, 225.5f, o, 678348);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_isosurf: cranium skipped: %s\n", e.what());
  }
  // f = |x - c| - 100: inside is f >= 0 here, i.e. outside the ball; counts are the same.
  {
    const auto sph = sphere(256, 100, 127.5);
    run_case("sphere r100 on 256^3", sph, 0.0f);
    isosurface::AdaptiveOptions o;
    o.max_error = 0.05;
    run_adaptive("sphere r100 on 256^3, eps0 0.05", sph, 0.0f, o, 377132);
  }
  // sparse: a small sphere in one 48^3 corner of a 384^3 volume
  run_case("sparse: r16 sphere in a 384^3 corner", sphere(384, 16, 24), 0.0f);
  return 0;
}
