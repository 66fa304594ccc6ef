#include "render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/core.hpp>

#include "core/image.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"

namespace fest::terrainlod_tool {

namespace {

// Bilinear sample of an 8-bit grey or RGB image at texture coordinates (u, v), v up,
// clamped to the image (tile textures are sampled up to their edges).
cv::Vec3d sample(const cv::Mat& img, double u, double v) {
  const double x = std::clamp(u * img.cols - 0.5, 0.0, img.cols - 1.0);
  const double y = std::clamp((1 - v) * img.rows - 0.5, 0.0, img.rows - 1.0);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
  const double fx = x - x0, fy = y - y0;
  cv::Vec3d out;
  for (int k = 0; k < 3; ++k) {
    auto at = [&](int yy, int xx) {
      return img.channels() == 1 ? static_cast<double>(img.at<std::uint8_t>(yy, xx)) : static_cast<double>(img.at<cv::Vec3b>(yy, xx)[k]);
    };
    out[k] = (1 - fy) * ((1 - fx) * at(y0, x0) + fx * at(y0, x1)) + fy * ((1 - fx) * at(y1, x0) + fx * at(y1, x1));
  }
  return out;
}

}  // namespace

std::string render_png(const Mesh& mesh, const terrainlod::Camera& cam, const RenderTextures* textures) {
  const bool textured = textures != nullptr && mesh.has_vertex_texcoords2D();
  using V = OpenMesh::Vec3d;
  const V eye(cam.eye[0], cam.eye[1], cam.eye[2]);
  const V f = (V(cam.target[0], cam.target[1], cam.target[2]) - eye).normalized();
  const V r = OpenMesh::cross(f, V(cam.up[0], cam.up[1], cam.up[2])).normalized();
  const V u = OpenMesh::cross(r, f);
  const double fpx = (cam.height / 2.0) / std::tan(cam.fovy_deg * M_PI / 360.0);
  const int W = cam.width, H = cam.height;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(235, 240, 245));  // pale sky
  std::vector<float> depth(static_cast<std::size_t>(W) * H, std::numeric_limits<float>::infinity());
  const V sun = V(-1, 1, 2).normalized();
  for (auto fh : mesh.faces()) {
    V p[3];
    double sx[3], sy[3], sz[3], tu[3] = {0, 0, 0}, tv[3] = {0, 0, 0};
    int k = 0;
    bool behind = false;
    for (auto vh : mesh.fv_range(fh)) {
      if (k == 3) break;
      p[k] = mesh.point(vh);
      if (textured) tu[k] = mesh.texcoord2D(vh)[0], tv[k] = mesh.texcoord2D(vh)[1];
      const V d = p[k] - eye;
      sz[k] = OpenMesh::dot(d, f);
      if (sz[k] < cam.near) behind = true;
      sx[k] = W / 2.0 + fpx * OpenMesh::dot(d, r) / sz[k];
      sy[k] = H / 2.0 - fpx * OpenMesh::dot(d, u) / sz[k];
      ++k;
    }
    if (k != 3 || behind) continue;  // previews skip triangles crossing the near plane
    V n = OpenMesh::cross(p[1] - p[0], p[2] - p[0]);
    if (n.norm() == 0) continue;
    n.normalize();
    if (n[2] < 0) n = -n;
    const double shade = 0.35 + 0.65 * std::max(0.0, OpenMesh::dot(n, sun));
    OpenMesh::Vec3uc c(200, 200, 200);
    if (mesh.has_face_colors()) c = mesh.color(fh);
    const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (area == 0) continue;
    const cv::Mat& texture = textured ? textures->images[static_cast<std::size_t>(textures->face_image[fh.idx()])] : img;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({sx[0], sx[1], sx[2]}))));
    const int x1 = std::min(W - 1, static_cast<int>(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({sy[0], sy[1], sy[2]}))));
    const int y1 = std::min(H - 1, static_cast<int>(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
        const double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
        const double w2 = 1 - w0 - w1;
        // A hair of tolerance: a pixel centre on an edge shared by two triangles belongs to
        // both (the depth test picks one) rather than, by rounding, to neither.
        if (w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9) continue;
        // Perspective-correct depth: 1/z is linear in screen space.
        const float z = static_cast<float>(1.0 / (w0 / sz[0] + w1 / sz[1] + w2 / sz[2]));
        float& zb = depth[static_cast<std::size_t>(y) * W + x];
        if (z >= zb) continue;
        zb = z;
        if (textured) {
          // Perspective-correct texture coordinates: u/z and v/z are linear in screen space.
          const double tex_u = z * (w0 * tu[0] / sz[0] + w1 * tu[1] / sz[1] + w2 * tu[2] / sz[2]);
          const double tex_v = z * (w0 * tv[0] / sz[0] + w1 * tv[1] / sz[1] + w2 * tv[2] / sz[2]);
          const cv::Vec3d t = sample(texture, tex_u, tex_v);
          img.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<unsigned char>(std::lround(t[0])), static_cast<unsigned char>(std::lround(t[1])),
                                              static_cast<unsigned char>(std::lround(t[2])));
          continue;
        }
        img.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<unsigned char>(c[0] * shade), static_cast<unsigned char>(c[1] * shade),
                                            static_cast<unsigned char>(c[2] * shade));
      }
  }
  Image out;
  out.pixels = img;
  return formats::write_image(out, formats::Format::png);
}

}  // namespace fest::terrainlod_tool
