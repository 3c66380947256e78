// A picture that checks an answer to the exam's viewing problem: the sphere drawn through the
// answer's gluLookAt and gluPerspective, lit from the eye with two-sided lighting so that the
// inside of the half behind the near plane shows, and the share of the window it covers measured
// from the pixels.
#pragma once

#include "glass/geometry/sphere_view.h"

namespace glass::course {

struct SphereViewMeasurement {
  int width = 0, height = 0;   // the window
  int rows = 0, columns = 0;   // rows and columns holding sphere pixels
  bool drawn = false;          // the context was made (and the PNG written, when asked)
  double heightShare() const { return height > 0 ? static_cast<double>(rows) / height : 0.0; }
  double widthShare() const { return width > 0 ? static_cast<double>(columns) / width : 0.0; }
};

// The window is `heightPixels` high and as wide as the answer's aspect ratio says. Draws into a
// new context, writes the PNG when `path` is not null, and measures.
SphereViewMeasurement renderSphereView(const geometry::SphereViewSolution& solution, double radius, int heightPixels,
                                       const char* path);

}  // namespace glass::course
