// The metrics of GLUT's nine fonts as freeglut 3 has them: each bitmap font's line height
// (glutBitmapHeight), the rows of its glyph box below the baseline (the yorig freeglut passes to
// glBitmap) and every character's advance (glutBitmapWidth); each stroke font's line height
// (glutStrokeHeight) and every character's advance in model units (glutStrokeWidthf). glass
// draws its own glyphs (glut/font_glyphs.h), but moves the raster position and the modelview
// matrix by these numbers, so that text and whatever a program lays out around it (with
// glutBitmapLength, glutStrokeLength) land where they land with freeglut.
#pragma once

#include <cstdint>

namespace glass::gl::glut {

enum class BitmapFont {
  Fixed9By15,
  Fixed8By13,
  TimesRoman10,
  TimesRoman24,
  Helvetica10,
  Helvetica12,
  Helvetica18,
};
inline constexpr int kBitmapFontCount = 7;

struct BitmapFontMetrics {
  int height;   // glutBitmapHeight: the distance from one line's baseline to the next
  int descent;  // rows of the glyph box below the baseline (freeglut's yorig); xorig is 0
};

const BitmapFontMetrics& bitmapFontMetrics(BitmapFont font);

// glutBitmapWidth: the raster position's x move for `character` (1 to 255), 0 outside.
int bitmapAdvance(BitmapFont font, int character);

enum class StrokeFont { Roman, MonoRoman };
inline constexpr int kStrokeFontCount = 2;

// glutStrokeHeight: the distance between lines, in model units.
float strokeFontHeight(StrokeFont font);

// freeglut's stroke fonts have characters 32 to 127 only; glutStrokeCharacter ignores others
// (and does not move).
bool hasStrokeCharacter(StrokeFont font, int character);

// glutStrokeWidthf: the x translation after `character`, 0 for a character the font lacks.
float strokeAdvance(StrokeFont font, int character);

}  // namespace glass::gl::glut
