// glass's glyphs (glut/font_glyphs.h) as the line strips glutStrokeCharacter draws: the centres
// of neighbouring set cells of the 5 x 9 grid joined by lines, in the stroke fonts' model units
// (capitals 100 units tall on the baseline y = 0, descenders to -33.33, as GLUT's Roman fonts).
#pragma once

#include <vector>

#include "glut/font_metrics.h"

namespace glass::gl::glut {

struct StrokePoint {
  float x;
  float y;
};
using StrokeStrip = std::vector<StrokePoint>;

// The strips of `character`, from x = 0 to about its advance; none for a blank or a character
// the font lacks.
std::vector<StrokeStrip> glyphStrokes(StrokeFont font, int character);

}  // namespace glass::gl::glut
