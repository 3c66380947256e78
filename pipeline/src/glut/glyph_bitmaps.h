// glass's glyphs (glut/font_glyphs.h) as the bitmaps glutBitmapCharacter hands to glBitmap, one
// style per GLUT bitmap font: rows taller for the large fonts, stems doubled where the font is
// large enough to carry them, each glyph centred on its character's freeglut advance.
#pragma once

#include <cstdint>
#include <vector>

#include "glut/font_metrics.h"

namespace glass::gl::glut {

// A glBitmap argument list. The box is the font's (its height, baseline `yorig` rows up) and at
// least the character's advance wide; a glyph wider than a narrow advance (i, l in the small
// proportional fonts) reaches past it, by a negative-going xorig and a wider box, and the next
// character overlaps it as freeglut's overlapping glyphs do.
struct GlyphBitmap {
  int width = 0;
  int height = 0;
  float xorig = 0.0f;
  float yorig = 0.0f;
  float xmove = 0.0f;  // the character's advance (glutBitmapWidth)
  // Rows bottom first, each (width + 7) / 8 bytes, the leftmost pixel in a byte's high bit: the
  // layout glBitmap reads with GL_UNPACK_LSB_FIRST false and GL_UNPACK_ALIGNMENT 1.
  std::vector<std::uint8_t> bits;
};

GlyphBitmap glyphBitmap(BitmapFont font, int character);

}  // namespace glass::gl::glut
