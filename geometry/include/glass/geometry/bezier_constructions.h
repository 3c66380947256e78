// Exact rational Bezier forms of the conics and quadrics of the course (study guide, section 2.4,
// lectures 14-15, and the exam's Bezier questions, section 4.1 item 4).
//
// The key fact: the arc of a circle from angle a0 to a1 (0 < a1 - a0 < pi) is the rational
// quadratic with end points on the circle, middle control point at the intersection of the end
// tangents, c + r (cos m, sin m) / cos(h), and middle weight cos(h), where m = (a0 + a1) / 2 and
// h = (a1 - a0) / 2 (end weights 1, the standard form, equation (14)). Rotating such a profile
// curve about an axis multiplies weights: a surface of revolution is the tensor product of the
// profile and an arc (see revolve()).
#pragma once

#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/bezier_surface.h"

#include <glm/vec3.hpp>

#include <vector>

namespace glass::geometry {

// The circle center + radius (cos a xAxis + sin a yAxis); the axes should be orthonormal.
struct CirclePlacement {
  glm::dvec3 center{0.0};
  double radius = 1.0;
  glm::dvec3 xAxis{1.0, 0.0, 0.0};
  glm::dvec3 yAxis{0.0, 1.0, 0.0};
};

// The rational quadratic in standard form (equation (14)): end weights 1, middle weight w.
// w < 1 gives an ellipse arc, w = 1 a parabola, w > 1 a hyperbola (Figure 2.6).
BezierCurve rationalQuadratic(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, double middleWeight);

// The arc of the circle from startAngle to endAngle (radians, 0 < endAngle - startAngle < pi), a
// rational quadratic. The exam's arc of the unit circle for 0 <= alpha <= 2 pi / 3 is
// circularArc(0, 2 pi / 3): control points (1, 0), (1, sqrt 3), (-1/2, sqrt 3 / 2), weights
// 1, 1/2, 1.
BezierCurve circularArc(double startAngle, double endAngle, const CirclePlacement& circle = {});

// The whole circle as arcCount >= 3 equal arcs (each below pi), counter-clockwise from angle 0.
std::vector<BezierCurve> fullCircle(int arcCount = 3, const CirclePlacement& circle = {});

// The exam's curvilinear triangle in the plane z = 0, a rational patch of bi-degree (1, 2).
//
// How the exam text is read: it says "x^2 + y^2 >= 0, x <= 1, y <= 1, z = 0". x^2 + y^2 >= 0 holds
// everywhere and would leave an unbounded region, so the intended inequality is x^2 + y^2 >= 1:
// the region outside the unit circle and inside the corner x <= 1, y <= 1 of the first quadrant,
// bounded by the quarter arc of the unit circle from (1, 0) to (0, 1) and the segments of the lines
// x = 1 and y = 1 that meet at (1, 1). The arc touches both lines at its ends (so the triangle's
// angles there are zero) and the lines meet at a right angle at (1, 1).
//
// The patch: v (degree 2) runs along the arc, P0 = (1, 0), P1 = (1, 1), P2 = (0, 1) with weights
// 1, sqrt 2 / 2, 1; u (degree 1) runs from the arc to the corner, whose row is (1, 1) three times
// with the same weights. Equal weights in both rows make S(u, v) = (1 - u) C(v) + u (1, 1): the
// segment from each arc point to the corner, and these segments sweep the triangle exactly because
// (1, 0) and (0, 1) are the points where the tangents from (1, 1) touch the circle. The sides are
// v = 0 (on x = 1), v = 1 (on y = 1), u = 0 (the arc); u = 1 collapses to the corner.
BezierSurface curvilinearTriangle();

// The frame of a surface of revolution: the point with distance rho from the axis, height h and
// angle a is origin + h axis + rho (cos a zeroDirection + sin a quarterDirection). The three
// directions should be orthonormal with (zeroDirection, quarterDirection, axis) right-handed; then
// normals point away from the axis where the profile rises.
struct RevolutionFrame {
  glm::dvec3 origin{0.0};
  glm::dvec3 axis{0.0, 0.0, 1.0};
  glm::dvec3 zeroDirection{1.0, 0.0, 0.0};
  glm::dvec3 quarterDirection{0.0, 1.0, 0.0};
};

// The surface swept by a profile curve (x = distance from the axis, y = height; z is ignored)
// turning from startAngle to endAngle (0 < endAngle - startAngle < pi). u runs along the angle
// (degree 2), v along the profile. Control point (i, j) is the profile point j turned onto the arc
// control point i, with weight w_arc(i) w_profile(j).
BezierSurface revolve(const BezierCurve& profile, double startAngle, double endAngle, const RevolutionFrame& frame = {});

// Patches of the quadrics, each a rational patch with angle ranges below pi. Axis z, angle from x
// towards y; u is the angle around the axis.
BezierSurface cylinderPatch(double radius, double height, double startAngle, double endAngle);  // z in [0, height]
BezierSurface conePatch(double radius, double height, double startAngle, double endAngle);  // base at z = 0, apex (0, 0, height)
BezierSurface spherePatch(double radius, double startLongitude, double endLongitude, double startLatitude,
                          double endLatitude);
// The sphere as eight patches (four longitude quarters times two hemispheres).
std::vector<BezierSurface> spherePatches(double radius);

// The torus of the exam (section 4.1, item 3):
//   x = (R + r cos theta) sin phi,  y = r sin theta,  z = (R + r cos theta) cos phi,
// the tube circle (angle theta) turned about the y axis (angle phi, from +z towards +x).
// u runs along phi (degree 2), v along theta (degree 2); normals point out of the tube.
BezierSurface torusPatch(double majorRadius, double minorRadius, double startPhi, double endPhi, double startTheta,
                         double endTheta);

// The exam's 1/16 of the torus, "defined by x >= 0, y <= 0, z >= 0".
//
// How the exam text is read: x >= 0 and z >= 0 give phi in [0, pi/2] (a quarter turn); y <= 0 gives
// sin theta <= 0, theta in [-pi, 0], half of the tube. Together that is 1/8 of the torus, and
// half a tube circle is not one rational quadratic with positive weights (it needs middle weight
// cos(pi/2) = 0). The 1/16 patch is one of its two halves: the outer one, theta in [-pi/2, 0]
// (distance from the axis >= R), or the inner one, theta in [-pi, -pi/2]. Control points (i along
// phi, j along theta from -pi/2 to 0) of the outer piece, weights in brackets (s = sqrt 2 / 2):
//   i = 0 (phi = 0):    (0, -r, R) [1]       (0, -r, R+r) [s]        (0, 0, R+r) [1]
//   i = 1:              (R, -r, R) [s]       (R+r, -r, R+r) [1/2]    (R+r, 0, R+r) [s]
//   i = 2 (phi = pi/2): (R, -r, 0) [1]       (R+r, -r, 0) [s]        (R+r, 0, 0) [1]
enum class TorusSixteenth { Outer, Inner };
BezierSurface torusSixteenth(double majorRadius, double minorRadius, TorusSixteenth piece = TorusSixteenth::Outer);

// The whole torus as sixteen such patches: index 4 k + l covers phi in [k pi/2, (k+1) pi/2] and
// theta in [l pi/2 - pi, (l+1) pi/2 - pi].
std::vector<BezierSurface> torusPatches(double majorRadius, double minorRadius);

}  // namespace glass::geometry
