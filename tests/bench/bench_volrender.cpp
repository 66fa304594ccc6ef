// volrender against VTK 9.1's CPU ray-cast mapper (vtkFixedPointVolumeRayCastMapper,
// offscreen, run under Xvfb) on the Cranium CT, same view, transfer function, sample
// distance and shading (docs/volrender.md "Performance"). One JSON line per case: seconds
// per frame (best and median of N), the process's CPU seconds per frame (user + system, all
// threads: the figure to compare on a shared, loaded machine), samples, skipped samples.
//
//   xvfb-run -a bench_volrender [--quick] [--frames N] [cranium.nrrd]
//   --quick: only the shaded DVR at 2 threads (--threads 1: at 1), and VTK at the same
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkFixedPointVolumeRayCastMapper.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"
#include "raycast/render.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"

using namespace fest;
using Clock = std::chrono::steady_clock;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Timing {
  double best_s, median_s, cpu_best_s, cpu_median_s;
};

Timing timed(int n, const std::function<void()>& f) {
  std::vector<double> t, c;
  for (int k = 0; k < n; ++k) {
    const auto s = Clock::now();
    const double c0 = cpu_seconds();
    f();
    c.push_back(cpu_seconds() - c0);
    t.push_back(std::chrono::duration<double>(Clock::now() - s).count());
  }
  std::sort(t.begin(), t.end());
  std::sort(c.begin(), c.end());
  return {t.front(), t[t.size() / 2], c.front(), c[c.size() / 2]};
}

void print(nlohmann::json j) { std::printf("%s\n", j.dump().c_str()), std::fflush(stdout); }

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  bool quick = false;
  int quick_threads = 2;
  int frames = 5;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--quick") quick = true;
    else if (arg == "--frames" && a + 1 < argc) frames = std::max(1, std::atoi(argv[++a]));
    else if (arg == "--threads" && a + 1 < argc) quick_threads = std::max(1, std::atoi(argv[++a]));
    else path = arg;
  }
  if (path.empty()) {
    const char* d = std::getenv("FEST_TESTDATA");
    path = std::string(d ? d : (std::string(std::getenv("HOME")) + "/.cache/fest/testdata")) + "/volumes/cranium.nrrd";
  }
  std::size_t nans = 0;
  const auto g = volume_pyramid::to_grid(formats::read_volume_source(formats::load_input(path), {}), nans);
  float lo = g.values[0], hi = lo;
  for (float v : g.values) lo = std::min(lo, v), hi = std::max(hi, v);
  const auto pts = raycast::preset_transfer_function("ct-skin-bone", lo, hi);
  const raycast::TransferFunction tf(pts, lo, hi, raycast::OpacityMode::opacity, 1.0);
  // Built once per volume, like VTK's gradient tables (its warm-up frame below): the
  // pyramid (finest level 2 = 4^3 cells, as volrender builds it) and the shading volume.
  const auto tb0 = Clock::now();
  const volume_pyramid::MinMaxPyramid pyr(g, 2, 2);
  const auto shading = raycast::shading_volume(g, 2);
  print({{"case", "per-volume tables"}, {"method", "volrender"}, {"pyramid_and_shading_volume_s",
         std::chrono::duration<double>(Clock::now() - tb0).count()}, {"pyramid_bytes", pyr.bytes()}});
  const auto a = g.world(0, 0, 0);
  const auto b = g.world(double(g.dims[0] - 1), double(g.dims[1] - 1), double(g.dims[2] - 1));
  const raycast::Vec3 centre{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  const double radius = raycast::norm(raycast::Vec3{b[0] - a[0], b[1] - a[1], b[2] - a[2]}) / 2;
  const auto cam = raycast::orbit_camera(centre, radius, 150, 15, 0, 30, 1, 512, 512);

  struct Case {
    const char* name;
    raycast::Mode mode;
    bool shade;
    int threads;
    bool skip;
    double ert = 0.995;
  };
  for (const Case c : {Case{"dvr shaded ct-skin-bone", raycast::Mode::dvr, true, 2, true},
                       Case{"dvr shaded ct-skin-bone", raycast::Mode::dvr, true, 1, true},
                       // VTK's mapper stops a ray when the remaining opacity falls below 0xff in
                       // 15-bit fixed point (VTKKWRCHelper_CompositeColorAndCheckEarlyTermination):
                       // A > 1 - 255/32767 = 0.99222
                       Case{"dvr shaded ct-skin-bone, ERT as VTK's", raycast::Mode::dvr, true, 2, true, 1 - 255.0 / 32767},
                       Case{"dvr shaded ct-skin-bone, ERT as VTK's", raycast::Mode::dvr, true, 1, true, 1 - 255.0 / 32767},
                       Case{"dvr shaded ct-skin-bone, no ESS", raycast::Mode::dvr, true, 2, false},
                       Case{"mip", raycast::Mode::mip, false, 2, true},
                       Case{"iso 225.5", raycast::Mode::iso, true, 2, true}}) {
    if (quick && !(c.mode == raycast::Mode::dvr && c.threads == quick_threads && c.skip)) continue;
    raycast::RenderOptions o;
    o.mode = c.mode, o.shade = c.shade, o.threads = c.threads, o.skip_empty = c.skip;
    o.step = 0.5;
    o.ert = c.ert;
    o.gradient_cache = true;
    o.isos = {{225.5, 1.0, std::nullopt}};
    raycast::RenderedImage img;
    const Timing t = timed(frames, [&] { img = raycast::render(g, &pyr, tf, cam, o, nullptr, nullptr, &shading); });
    print({{"case", c.name}, {"method", "volrender"}, {"size", "512x512"}, {"threads", c.threads}, {"best_s", t.best_s},
           {"median_s", t.median_s}, {"cpu_best_s", t.cpu_best_s}, {"cpu_median_s", t.cpu_median_s},
           {"ert", c.ert}, {"samples", img.stats.samples}, {"skipped", img.stats.skipped},
           {"skipped_fraction", double(img.stats.skipped) / double(img.stats.samples + img.stats.skipped)}});
  }

  // VTK: the same data, view, transfer function (opacity per unit distance = 1 voxel of the
  // smallest spacing), sample distance 0.5 voxel, Phong 0.3/0.7/0.2/20.
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(int(g.dims[0]), int(g.dims[1]), int(g.dims[2]));
  img->SetSpacing(g.axes[0], g.axes[4], g.axes[8]);
  img->SetOrigin(g.origin[0], g.origin[1], g.origin[2]);
  auto arr = vtkSmartPointer<vtkFloatArray>::New();
  arr->SetNumberOfTuples(vtkIdType(g.size()));
  std::copy(g.values.begin(), g.values.end(), arr->GetPointer(0));
  img->GetPointData()->SetScalars(arr);
  auto color = vtkSmartPointer<vtkColorTransferFunction>::New();
  auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  for (const auto& p : pts) {
    color->AddRGBPoint(p.value, p.r, p.g, p.b);
    opacity->AddPoint(p.value, p.a);
  }
  const double hmin = std::min({g.axes[0], g.axes[4], g.axes[8]});
  auto prop = vtkSmartPointer<vtkVolumeProperty>::New();
  prop->SetColor(color);
  prop->SetScalarOpacity(opacity);
  prop->SetScalarOpacityUnitDistance(hmin);
  prop->SetInterpolationTypeToLinear();
  prop->ShadeOn();
  prop->SetAmbient(0.3), prop->SetDiffuse(0.7), prop->SetSpecular(0.2), prop->SetSpecularPower(20);
  auto mapper = vtkSmartPointer<vtkFixedPointVolumeRayCastMapper>::New();
  mapper->SetInputData(img);
  mapper->SetSampleDistance(0.5 * hmin);
  mapper->SetNumberOfThreads(2);
  mapper->AutoAdjustSampleDistancesOff();
  auto vol = vtkSmartPointer<vtkVolume>::New();
  vol->SetMapper(mapper);
  vol->SetProperty(prop);
  auto ren = vtkSmartPointer<vtkRenderer>::New();
  ren->AddVolume(vol);
  auto win = vtkSmartPointer<vtkRenderWindow>::New();
  win->SetOffScreenRendering(1);
  win->SetSize(512, 512);
  win->AddRenderer(ren);
  vtkCamera* vc = ren->GetActiveCamera();
  vc->SetPosition(cam.eye.data());
  const raycast::Vec3 f = raycast::operator+(cam.eye, cam.forward);
  vc->SetFocalPoint(f.data());
  vc->SetViewUp(cam.up.data());
  vc->SetViewAngle(30);
  ren->ResetCameraClippingRange();
  for (int threads : {2, 1}) {
    if (quick && threads != quick_threads) continue;
    mapper->SetNumberOfThreads(threads);
    win->Render();  // warm-up (builds the mapper's tables)
    const Timing t = timed(frames, [&] {
      vol->Modified();
      win->Render();
    });
    print({{"case", "dvr shaded ct-skin-bone"}, {"method", "vtkFixedPointVolumeRayCastMapper"}, {"size", "512x512"},
           {"threads", threads}, {"best_s", t.best_s}, {"median_s", t.median_s}, {"cpu_best_s", t.cpu_best_s},
           {"cpu_median_s", t.cpu_median_s}});
  }
  return 0;
}
