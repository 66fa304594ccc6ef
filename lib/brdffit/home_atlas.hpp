#pragma once
// The texture atlas of the photographs (docs/brdffit.md §4; chapter 8 §8.6.3, Fig.
// 8.13): triangles are charted in the pixels of their home image (lumitexel_builder.hpp's
// step 1), so the atlas holds the photographs' own pixels of the object, background
// discarded. Texel centres fall on pixel centres (charts move by whole texels), so a texel
// inside a triangle reads its pixel unfiltered.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/texture_atlas.hpp"
#include "brdffit/texture_bake.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit {

// Flat map: a triangle with a home image goes to group = that image, its corners at the
// pixels where the image shows them (distorted projection) + 0.5 (pixel centres are at
// integer coordinates, texel centres at half-integers). Triangles without a home image
// (never seen) are charted by axis projection (texture_atlas.hpp) in groups after the
// images, at the mean pixel footprint of the seen ones. Throws bad_input when no triangle
// has a home image or the sizes disagree.
FlatTriangles home_image_projection(const reflectance::TriangleMesh& mesh, const std::vector<ImageView>& views,
                                    const HomeAssignment& home);

// Fills the texels (of `texels`, built on the atlas of home_image_projection) whose
// triangle has home image `image` from that image's radiance, bilinearly at the
// projection of the texel's surface point. `atlas_rgb`: CV_32FC3, atlas size; texels of
// other images are left alone, so call once per home image as the images stream in.
void sample_home_image(const reflectance::TriangleMesh& mesh, const TexelSurface& texels, const HomeAssignment& home,
                       std::size_t image, const ImageView& view, const cv::Mat& radiance, cv::Mat& atlas_rgb);

}  // namespace fest::brdffit
