#pragma once
// Texture tiles (docs/terrainlod.md, textures; man5 terrainlod-pyramid): every tile of every level carries T x T
// texels. The image covering the DEM is resampled once to the leaf canvas of 2^L T texels
// per side (the padded square of the pyramid, north row first like every image), each
// coarser canvas is the 2 x 2 box mean of the finer one (the mipmap filter), and a tile's
// texture is its T x T square of its level's canvas. Texel (c, r) of tile (l, x, y)
// covers grid cells [x S + c s, x S + (c+1) s] east and the r-th row of texels from the
// tile's north edge, with S = 2^(L-l) B cells per tile and s = S / T: texture
// coordinates (u, v) = ((gx - x S) / S, (gy - y S) / S) put tile corners at 0 and 1.
//
// Pixels are 8-bit with 1 (grey) or 3 (RGB) channels.

#include <opencv2/core.hpp>

#include "terrainlod/height_grid.hpp"

namespace fest::terrainlod {

struct TextureLayout {
  int levels = 0;          // L
  int tile = 64;           // B: leaf tile side in DEM cells
  int texels = 64;         // T: texels per tile side
  int width = 0, height = 0;  // DEM samples
  int canvas(int level) const { return texels << level; }  // texels per side of a level's canvas
};

// Any fest image -> texture pixels: 16-bit scaled to 8 (rounded), alpha dropped, grey
// kept grey. Float images are refused (bad_input): map them to 8 or 16 bits explicitly.
cv::Mat texture_pixels(const cv::Mat& image);

// How an image lies on the DEM.
enum class ImagePlacement {
  extent,   // the image's outer edges are the DEM's outer samples (the surface the mesh spans)
  samples,  // one pixel per DEM sample, pixel centres on the samples (a W x H image)
};

// The placement of a W' x H' image on a W x H-sample DEM: `samples` when it has exactly
// one pixel per sample, else `extent` -- which needs the DEM's aspect ratio in cells,
// (W - 1) : (H - 1), to within one pixel (bad_input otherwise, naming both sizes).
ImagePlacement place_image(int image_width, int image_height, int dem_width, int dem_height);

// Where an image lies on the DEM in general: grid point (gx, gy) (DEM samples, gy from
// the south) is at image pixel px = gx sx + ox, py = (H - 1 - gy) sy + oy (pixel centres
// at integers, rows from the north).
struct ImageFrame {
  double sx = 1, ox = 0, sy = 1, oy = 0;
};

// The frame of a placement (above) for an iw x ih image.
ImageFrame placement_frame(ImagePlacement placement, int image_width, int image_height, const TextureLayout& layout);

// The frame of a georeferenced image on a georeferenced DEM: both given by the centre of
// their south-west sample/pixel and their spacing (world units, north-up).
struct GridGeoreference {
  double origin_x = 0, origin_y = 0, dx = 1, dy = 1;
  int height = 0;  // rows
};
ImageFrame georeferenced_frame(const GridGeoreference& dem, const GridGeoreference& image);

// The leaf canvas for an image in any frame (bilinear, area-averaged first where the image
// has more pixels than texels, edges replicated outside it).
cv::Mat leaf_canvas(const cv::Mat& image, const ImageFrame& frame, const TextureLayout& layout);

// The leaf canvas (2^L T square, north row first). Bilinear resampling at the texel
// centres; where the image has more pixels than texels it is first reduced with area
// averaging (cv::INTER_AREA), so no level aliases. Outside the DEM (the pyramid's padding)
// the image's edge is replicated, as the heights are. An image already on the texel
// lattice (extent placement, (W-1) T / B x (H-1) T / B pixels) is copied exactly.
cv::Mat leaf_canvas(const cv::Mat& image, ImagePlacement placement, const TextureLayout& layout);

// The next coarser canvas: every texel the mean of its 2 x 2 children, rounded half up.
cv::Mat halve_canvas(const cv::Mat& canvas);

// Tile (level, x, y)'s texture: a T x T copy out of its level's canvas.
cv::Mat tile_texture(const cv::Mat& level_canvas, int level, int x, int y, int texels);

// A hillshaded, height-coloured W x H RGB image of the grid (one pixel per sample): Horn's
// gradient, sun from the north-west 45 degrees up, a hypsometric tint from the lowest
// (green) to the highest (white) sample. For `build --texture hillshade`.
cv::Mat hillshade_image(const HeightGrid& grid, double dx, double dy);

}  // namespace fest::terrainlod
