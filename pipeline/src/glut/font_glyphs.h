// glass's own glyphs for GLUT's fonts: printable ASCII (32 to 126) on a grid of 5 columns by 9
// rows, rows 0 to 6 above the baseline (row 6 sits on it) and rows 7 and 8 below it, for the
// descenders of g, j, p, q, y and the commas. The bitmap fonts draw these pixels, scaled
// (glut/glyph_bitmaps.cpp); the stroke fonts join neighbouring pixels with lines
// (glut/glyph_strokes.cpp).
//
// They are not the glyphs of GLUT's fonts (X11's Helvetica, Times and fixed fonts, and the
// Hershey-like Roman strokes), which glass does not have: text takes the place GLUT's text takes
// (the same positions, advances and line heights, glut/font_metrics.h), but its letters look
// different.
#pragma once

#include <cstdint>

namespace glass::gl::glut {

inline constexpr int kGlyphColumns = 5;
inline constexpr int kGlyphRows = 9;
inline constexpr int kGlyphBaselineRow = 6;

// The rows of a character's glyph, top first; bit 4 is the leftmost column. Characters outside
// 32..126 have the space's (empty) glyph.
const std::uint8_t* glyphRows(int character);

}  // namespace glass::gl::glut
