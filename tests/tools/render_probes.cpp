// Test and example tooling: draws the probe meshes of `lemtrace probes` (.vtp: triangles
// with per-vertex scalars) as a picture a person can look at -- an orthographic view
// along -z, each file's triangles coloured by its named scalar (viridis over that
// file's range, flat per triangle), painted from low to high z, with OpenCV: flat 2-D
// fills in painter's order rather than mesh_picture's z-buffer rasteriser, whose shaded
// perspective pictures are not what a probe map shows.
//
//   render_probes OUT.png SIZE PROBES.vtp:SCALAR [MORE.vtp:SCALAR ...]

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/dataset/vtk_convert.hpp"
#include "formats/input.hpp"
#include "mesh_picture.hpp"

int main(int argc, char** argv) {
  return fest::run_tool("render_probes", [&] {
    if (argc < 4) throw fest::usage_error("usage: render_probes OUT.png SIZE PROBES.vtp:SCALAR ...");
    const int size = std::atoi(argv[2]);
    if (size < 64 || size > 8192) throw fest::usage_error("SIZE {} is outside 64..8192", size);
    struct Tri {
      double x[3], y[3];
      double z, value;
    };
    std::vector<Tri> tris;
    double b[6] = {1e300, -1e300, 1e300, -1e300, 0, 0};
    for (int f = 3; f < argc; ++f) {
      const std::string arg = argv[f];
      const auto colon = arg.rfind(':');
      if (colon == std::string::npos) throw fest::usage_error("{}: expected FILE.vtp:SCALAR", arg);
      const std::string file = arg.substr(0, colon), name = arg.substr(colon + 1);
      const fest::formats::Input in = fest::formats::load_input(file);
      vtkSmartPointer<vtkDataSet> ds = fest::formats::to_vtk(fest::formats::parse(in, fest::formats::read_dataset));
      auto* poly = vtkPolyData::SafeDownCast(ds);
      if (!poly || poly->GetNumberOfPoints() == 0) throw fest::bad_input("{}: no polygon data", file);
      vtkDataArray* s = poly->GetPointData()->GetArray(name.c_str());
      if (!s) throw fest::bad_input("{}: no point array {}", file, name);
      double r[2];
      s->GetRange(r, 0);
      double fb[6];
      poly->GetBounds(fb);
      b[0] = std::min(b[0], fb[0]);
      b[1] = std::max(b[1], fb[1]);
      b[2] = std::min(b[2], fb[2]);
      b[3] = std::max(b[3], fb[3]);
      vtkCellArray* polys = poly->GetPolys();
      auto ids = vtkSmartPointer<vtkIdList>::New();
      polys->InitTraversal();
      while (polys->GetNextCell(ids)) {
        if (ids->GetNumberOfIds() != 3) continue;
        Tri t{};
        for (int k = 0; k < 3; ++k) {
          double p[3];
          poly->GetPoint(ids->GetId(k), p);
          t.x[k] = p[0];
          t.y[k] = p[1];
          t.z += p[2] / 3;
          t.value += s->GetComponent(ids->GetId(k), 0) / 3;
        }
        t.value = (t.value - r[0]) / std::max(r[1] - r[0], 1e-300);
        tris.push_back(t);
      }
    }
    const double extent = std::max({b[1] - b[0], b[3] - b[2], 1e-300});
    const int margin = size / 20;
    const double scale = (size - 2 * margin) / extent;
    cv::Mat image(size, size, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::Mat ramp(1, 256, CV_8UC1), colours;
    for (int i = 0; i < 256; ++i) ramp.at<uchar>(0, i) = static_cast<uchar>(i);
    cv::applyColorMap(ramp, colours, cv::COLORMAP_VIRIDIS);
    std::stable_sort(tris.begin(), tris.end(), [](const Tri& a, const Tri& c) { return a.z < c.z; });
    for (const Tri& t : tris) {
      cv::Point p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = cv::Point(static_cast<int>(std::lround(16 * (margin + (t.x[k] - b[0]) * scale))),
                         static_cast<int>(std::lround(16 * (size - margin - (t.y[k] - b[2]) * scale))));
      const int c = std::clamp(static_cast<int>(255.0 * t.value), 0, 255);
      const cv::Vec3b col = colours.at<cv::Vec3b>(0, c);
      cv::fillConvexPoly(image, p, 3, cv::Scalar(col[0], col[1], col[2]), cv::LINE_AA, 4);
    }
    cv::rectangle(image, cv::Point(margin - 1, margin - 1), cv::Point(size - margin, size - margin), cv::Scalar(160, 160, 160));
    fest::test_tools::write_png(argv[1], image);
    return 0;
  });
}
