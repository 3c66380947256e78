// The virtual trackball of `glass ifs3d view`: a drag of the mouse turns the object as if it were
// a ball under the hand, the turn kept as a unit quaternion (study guide, section 2.3). The
// pointer's window position is lifted onto a sphere of radius 1 (in units of half the window's
// smaller side) that blends into a hyperbolic sheet away from the centre (Bell's trackball, as in
// SGI's trackball.c), so that drags outside the ball still turn smoothly about the view axis.
#pragma once

#include <glass/geometry/quaternion.h>

#include <glm/vec3.hpp>

namespace glass::cli::view {

// The point under window position (x, y) (pixels, y down, as GLUT gives them) on the ball:
// x to the right, y up, z towards the viewer.
glm::dvec3 trackballPoint(double x, double y, int width, int height);

// The turn that takes the ball's point under (x0, y0) to the one under (x1, y1), about the axis
// through both and the ball's centre, in eye coordinates. No turn for a drag of no length.
geometry::Quaternion trackballDrag(double x0, double y0, double x1, double y1, int width, int height);

// The object's orientation after a drag: the drag's turn, given in eye coordinates, taken to
// world coordinates through the camera's axes (right, up and back, as gluLookAt builds them from
// eye, centre and up), then applied after the orientation so far. The result is normalised, so
// that rounding does not build up over many drags.
geometry::Quaternion turnByDrag(const geometry::Quaternion& orientation, const geometry::Quaternion& dragInEye,
                                const glm::dvec3& eye, const glm::dvec3& centre, const glm::dvec3& up);

} // namespace glass::cli::view
