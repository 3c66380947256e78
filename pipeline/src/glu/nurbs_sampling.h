// How finely GLU samples a NURBS piece (GLU 1.3 specification, section 7.6; the formulas of SGI's
// GLU, Mesa's libGLU).
//
// The sampling matrix maps control points to window pixels: the projection times the modelview
// matrix (the GL's current ones, or those of gluLoadSamplingMatrices when GLU_AUTO_LOAD_MATRIX is
// off), then x and y scaled by half the viewport's width and height; z is dropped. On the
// projected control points P_i of a Bezier piece of order k over a parameter range r:
//   GLU_PATH_LENGTH       the derivative is at most |B'| <= (k - 1) / r * max |P_i+1 - P_i| = m,
//                         so a step of t / m moves at most t pixels (t = GLU_SAMPLING_TOLERANCE);
//                         surfaces take t / (2 m) in each direction, as SGI's GLU does.
//   GLU_PARAMETRIC_ERROR  the second derivative is at most (k - 1)(k - 2) / r^2 * max |second
//                         difference| = d, and a chord over a step h is within d h^2 / 8 of the
//                         curve, so h = sqrt(8 t / d) (t = GLU_PARAMETRIC_TOLERANCE).
//   GLU_OBJECT_*          the same on the control points in object coordinates.
//   GLU_DOMAIN_DISTANCE   1 / GLU_U_STEP (and 1 / GLU_V_STEP) in parameter units.
// A piece with a control point behind the eye (w <= 0 after projection) takes 1 / GLU_U_STEP.
#pragma once

#include <array>
#include <vector>

#include "glu/nurbs_object.h"

namespace glass::gl::glu {

class NurbsSampler {
 public:
  // Reads the matrices now (from the GL with GLU_AUTO_LOAD_MATRIX).
  explicit NurbsSampler(const GLUnurbs& nurb);

  // The parameter step of a curve piece: `order` control points of `dimension` (3 or 4)
  // coordinates over [0, range].
  double curveStep(const std::vector<double>& points, int order, int dimension,
                   double range) const;

  // The parameter steps along u and v of a surface piece: uOrder x vOrder control points,
  // (i, j) at (i * vOrder + j) * dimension.
  std::array<double, 2> surfaceSteps(const std::vector<double>& points, int uOrder, int vOrder,
                                     int dimension, double uRange, double vRange) const;

  // GLU_CULLING: whether every control point lies outside the same clipping plane.
  bool outsideView(const std::vector<double>& points, int dimension) const;

 private:
  // A control point in the space the tolerance is measured in: window pixels (x, y, 0) or object
  // coordinates. False when it lies behind the eye.
  bool measure(const double* point, int dimension, double out[3]) const;
  bool measureAll(const std::vector<double>& points, int dimension,
                  std::vector<std::array<double, 3>>& out) const;

  const GLUnurbs& nurb_;
  double clip_[16];          // projection * modelview, column-major
  double halfWidth_ = 0.5, halfHeight_ = 0.5;
};

// The number of steps of `step` that cover `range`: at least 1, at most a bound that keeps a
// degenerate tolerance from exhausting memory.
int stepCount(double range, double step);

}  // namespace glass::gl::glu
