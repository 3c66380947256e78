// The Utah teaset -- Newell's teapot, teacup and teaspoon as bicubic Bezier patches -- in the
// arrangement freeglut 3 uses for glutSolidTeapot, glutSolidTeacup and glutSolidTeaspoon (and
// their wire forms): the patches of one quadrant or side, which glut/teaset_mesh.cpp evaluates and
// copies as freeglut does.
#pragma once

#include <span>

namespace glass::gl::glut {

struct TeasetPiece {
  std::span<const int[16]> patches;           // 16 control point indices each, 4 x 4 row-major
  std::span<const float[3]> controlPoints;   // x, y, z with z up
  float centreHeight;  // the height moved to y = 0 (freeglut's offset)
  // The first six patches are turned into the four quadrants about the vertical axis and the
  // others mirrored to the other side (the teapot, the teacup); otherwise each is drawn once.
  bool turnsAndMirrors;
  // The first rows of patches 3 and 5 collapse to points (the top of the teapot's lid, the
  // middle of its bottom): their normals are set straight up and down.
  bool fixesCollapsedRows;
};

extern const TeasetPiece kTeapot;
extern const TeasetPiece kTeacup;
extern const TeasetPiece kTeaspoon;

}  // namespace glass::gl::glut
