#pragma once
// A tiny 5x7 bitmap font for labels drawn into fest images (orientation letters, scale
// bars, panel titles of quick looks). Digits, A-Z, 'm' and 'x' (for "mm" and "2x"), and a
// few symbols; other lowercase letters are drawn as capitals, anything else as '?'.
// Each glyph sits in a 6x8 cell (one column and one row of space), times `scale`.

#include <array>
#include <string_view>

#include <opencv2/core.hpp>

namespace fest {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
constexpr int kGlyphCellWidth = 6, kGlyphCellHeight = 8;

// Seven rows of five bits (bit 4 = leftmost column) of a character's glyph.
const std::array<unsigned char, 7>& glyph_rows(char c) noexcept;

// The size in pixels of a line of text: width = cells * 6 * scale - scale (no trailing
// space), height = 7 * scale.
int text_width(std::string_view text, int scale = 1) noexcept;
inline int text_height(int scale = 1) noexcept { return kGlyphHeight * scale; }

// Draws `text` with its top-left corner at (x, y) into an 8-bit image of 1, 3 or 4
// channels (colour in the image's channel order: fest images are R, G, B); pixels outside
// the image are skipped, so text may run off an edge.
void draw_text(cv::Mat& image, int x, int y, std::string_view text, const cv::Scalar& colour, int scale = 1);

// A filled axis-aligned rectangle, clipped to the image (the same pixel types).
void fill_rect(cv::Mat& image, int x, int y, int width, int height, const cv::Scalar& colour);

}  // namespace fest
