#pragma once
// The marker detector (docs/markerpose.md §2-3): candidate quads, sub-pixel corners,
// unwarping of the interior, identification by a binary dictionary or by pattern
// templates. Grey 8-bit images in, markers with IDs and ordered corners out; no I/O.

#include <vector>

#include <opencv2/core.hpp>

#include "markers/dictionary.hpp"
#include "markers/pattern.hpp"
#include "markers/pose.hpp"
#include "markers/quads.hpp"

namespace fest::markers {

struct DetectorOptions {
  QuadOptions quads;
  const Dictionary* dictionary = nullptr;                // binary markers, or
  const std::vector<PatternTemplate>* patterns = nullptr;  // ARToolKit pattern markers
  double min_pattern_ncc = 0.75;      // pattern markers: correlation needed
  double max_border_errors = 0.2;     // fraction of border cells allowed to read white
  double min_contrast = 12;           // grey levels between the dark and light cells
  double uncertain_margin = 0.25;     // cells this close to the threshold (fraction of the
                                      // contrast) are erasures in the decoding
  bool refine_corners = true;
  bool edge_model = true;  // after identification, fit the blurred-step edge model (§2.4)
  double edge_sigma = -1;  // Gaussian smoothing (px) of the image the edges are fitted on;
                           // -1: 0.8 when image_noise() exceeds 2.5 grey levels, else none
  const CameraModel* camera = nullptr;  // lens distortion for the edge fit (optional)
};

struct Detection {
  int id = -1;
  Corners corners;     // top-left, top-right, bottom-right, bottom-left of the marker
  int bit_errors = 0;  // binary markers: corrected bits
  double score = 0;    // pattern markers: normalised cross-correlation
};

// Throws fest::Error (bad_input) when neither a dictionary nor patterns are given.
// Detections come sorted by id, then by the top-left corner (row-major): deterministic.
std::vector<Detection> detect_markers(const cv::Mat& grey8, const DetectorOptions& options);

// Robust estimate of the image's noise sigma, grey levels (median of neighbour differences).
double image_noise(const cv::Mat& grey8);

// Mean grey of the cells of an n x n grid laid over the quad (cell (r, c) covers
// [c, c+1] x [r, r+1] of the canonical square [0, n]^2 mapped onto the corners), from
// 3 x 3 bilinear samples in the middle half of each cell. Public for the tests.
std::vector<float> sample_cells(const cv::Mat& grey8, const Corners& corners, int n);

}  // namespace fest::markers
