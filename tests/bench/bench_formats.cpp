// Benchmarks of the format library against the libraries it stands on (the anchors),
// measured in the same process on the same files: one JSON line per case.
//
//   build/bin/bench_formats [TESTDATA_DIR]      (default: $FEST_TESTDATA)
//
// Cases: reading the bunny as OFF and writing/reading it as binary PLY (anchor:
// OpenMesh 9's own IO, which parses coordinates as float -- faster but not exact),
// decoding and encoding a PNG (anchors: cv::imdecode/imencode, which fest called before
// it used libpng directly: the same library underneath, so fest must be as fast),
// and fcompare's surface distance on the bunny (no anchor in Debian; absolute figure).
// Figures are the median of several runs, in milliseconds.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "compare/mesh_compare.hpp"
#include "formats/image/image_io.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median_ms(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    auto start = Clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void line(const char* bench, const std::string& input, double fest_ms, const char* anchor, double anchor_ms) {
  if (anchor_ms > 0)
    std::printf("{\"bench\":\"%s\",\"input\":\"%s\",\"fest_ms\":%.3f,\"anchor\":\"%s\",\"anchor_ms\":%.3f,"
                "\"ratio\":%.3f}\n",
                bench, input.c_str(), fest_ms, anchor, anchor_ms, fest_ms / anchor_ms);
  else
    std::printf("{\"bench\":\"%s\",\"input\":\"%s\",\"fest_ms\":%.3f}\n", bench, input.c_str(), fest_ms);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const char* env = std::getenv("FEST_TESTDATA");
  const std::string dir = argc > 1 ? argv[1] : (env ? env : "");
  const std::string bunny_path = dir + "/meshes/bunny00.off";
  const std::string png_path = dir + "/faces/astronaut.png";
  const std::string bunny_off = slurp(bunny_path);
  if (bunny_off.empty()) {
    std::fprintf(stderr, "bench_formats: no test data in '%s' (run scripts/fetch-test-data.sh)\n", dir.c_str());
    return 77;
  }
  using namespace fest::formats;
  const int runs = 7;

  // OFF text -> mesh
  fest::Mesh mesh;
  double fest_off = median_ms(runs, [&] { mesh = read_mesh(bunny_off, Format::off); });
  double om_off = median_ms(runs, [&] {
    fest::Mesh m;
    std::istringstream in(bunny_off);
    OpenMesh::IO::Options opt;
    OpenMesh::IO::read_mesh(m, in, ".off", opt);
  });
  line("mesh_read_off", "bunny00.off", fest_off, "OpenMesh 9.0 IO (float parse)", om_off);

  // mesh -> binary PLY, and back
  std::string ply;
  double fest_wply = median_ms(runs, [&] { ply = write_mesh(mesh, Format::ply); });
  double om_wply = median_ms(runs, [&] {
    std::ostringstream out;
    OpenMesh::IO::Options opt(OpenMesh::IO::Options::Binary);
    OpenMesh::IO::write_mesh(mesh, out, ".ply", opt);
  });
  line("mesh_write_ply_binary", "bunny00.off", fest_wply, "OpenMesh 9.0 IO", om_wply);
  std::string om_ply;
  {
    std::ostringstream out;
    OpenMesh::IO::Options opt(OpenMesh::IO::Options::Binary);
    OpenMesh::IO::write_mesh(mesh, out, ".ply", opt);
    om_ply = out.str();
  }
  double fest_rply = median_ms(runs, [&] { read_mesh(ply, Format::ply); });
  double om_rply = median_ms(runs, [&] {
    fest::Mesh m;
    std::istringstream in(om_ply);
    OpenMesh::IO::Options opt(OpenMesh::IO::Options::Binary);
    OpenMesh::IO::read_mesh(m, in, ".ply", opt);
  });
  line("mesh_read_ply_binary", "bunny00.off", fest_rply, "OpenMesh 9.0 IO", om_rply);

  // PNG decode
  const std::string png = slurp(png_path);
  if (!png.empty()) {
    double fest_png = median_ms(runs, [&] { read_image(png, Format::png); });
    double cv_png = median_ms(runs, [&] {
      cv::Mat buf(1, static_cast<int>(png.size()), CV_8U, const_cast<char*>(png.data()));
      cv::imdecode(buf, cv::IMREAD_UNCHANGED);
    });
    line("image_read_png", "astronaut.png", fest_png, "OpenCV 4.6 imdecode", cv_png);
    // PNG encode at fest's default level 6, the anchor given the same settings (and the
    // same RGB -> BGR order it expects, swapped outside the timing).
    const fest::Image decoded = read_image(png, Format::png);
    cv::Mat bgr;
    if (decoded.pixels.channels() == 3) cv::cvtColor(decoded.pixels, bgr, cv::COLOR_RGB2BGR);
    else bgr = decoded.pixels;
    double fest_wpng = median_ms(runs, [&] { write_image(decoded, Format::png); });
    double cv_wpng = median_ms(runs, [&] {
      std::vector<uchar> out;
      cv::imencode(".png", bgr, out, {cv::IMWRITE_PNG_COMPRESSION, 6});
    });
    line("image_write_png", "astronaut.png", fest_wpng, "OpenCV 4.6 imencode", cv_wpng);
  }

  // Surface distance of the bunny to itself: 37 706 vertices + 100 000 samples a side.
  double dist = median_ms(3, [&] { fest::compare::surface_distance(mesh, mesh, 100000); });
  line("surface_distance", "bunny00.off", dist, "", 0);
  return 0;
}
