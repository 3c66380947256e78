// The study guide's exam viewing problem (section 4.1, question 1): an eye looks at a sphere of
// centre C and radius r; choose gluLookAt and gluPerspective so that the sphere's image fills a
// given share of the window's height and width and exactly a given part of the sphere is visible.
//
// The part visible is set by the near clipping plane, perpendicular to the line of sight at
// distance n from the eye. Let d = |C - E| and n = d + t. The part of the sphere beyond the plane
// is a cap of height r - t, and by Archimedes' hat-box theorem a zone of a sphere has area
// 2 pi r (height), so the cap is the fraction f = (r - t) / (2r) of the sphere:
//   t = r (1 - 2f),   "exactly one half visible": t = 0, the plane through the centre.
// For f <= 1/2 (t >= 0) all of the cap is seen, from inside, through the opening the plane cuts:
// every point of the cap is behind the sphere's front half as seen from E, and that front half is
// clipped away. The outline of the image is the rim of the opening, a circle of radius
// rho = sqrt(r^2 - t^2) at distance n, centred on the line of sight; the cap itself stays inside
// it (its cross-sections shrink and move away from the eye beyond the rim).
// With the rim's diameter 2 rho a share h of the window's height at distance n, and a share w of
// its width:
//   window height at distance n:  2 n tan(fovy / 2) = 2 rho / h  =>  fovy = 2 atan(rho / (h n))
//   window width at distance n:   aspect * (2 rho / h) = 2 rho / w  =>  aspect = h / w
//   near = n; far must reach the back of the sphere, d + r. Exactly d + r puts the sphere's
//   farthest point on the far plane, where rounding can clip it, so far = d + 2r is given.
// The exam: E = (0, 2, -1), C = (1, 4, 1), r = 1, h = 2/3, w = 1/2, f = 1/2 gives d = 3, t = 0,
// fovy = 2 atan(1/2) = 53.13 degrees, aspect = 4/3, near = 3, far >= 4 (5 given): at the centre's distance
// the window is 4 wide and 3 high, and the sphere's great circle, 2 across, fills 1/2 and 2/3.
// The window itself must then have the aspect ratio h / w, 4:3, for the picture not to be
// stretched. gluLookAt(E, C, up) with any up not parallel to C - E: the image is a circle centred
// in the window, so the up vector only turns it about its centre.
#pragma once

#include <optional>
#include <string>

#include <glm/vec3.hpp>

namespace glass::geometry {

struct SphereViewProblem {
  glm::dvec3 eye{0.0, 2.0, -1.0};
  glm::dvec3 center{1.0, 4.0, 1.0};
  double radius = 1.0;
  double heightShare = 2.0 / 3.0;   // of the window's height, in (0, 1]
  double widthShare = 0.5;          // of the window's width, in (0, 1]
  double visibleFraction = 0.5;     // of the sphere's surface, in (0, 1/2]
  glm::dvec3 up{0.0, 1.0, 0.0};
};

struct SphereViewSolution {
  // gluLookAt(eye, center, up)
  glm::dvec3 eye, center, up;
  // gluPerspective(fovyDegrees, aspect, zNear, zFar)
  double fovyDegrees = 0.0, aspect = 1.0, zNear = 0.0, zFar = 0.0;
  // The working: distance to the centre, the near plane's offset t beyond the centre, and the
  // radius of the rim circle the near plane cuts.
  double distance = 0.0, planeOffset = 0.0, rimRadius = 0.0;
  double backDistance = 0.0;  // d + r, the least zFar that keeps all of the sphere
};

struct SphereViewResult {
  std::optional<SphereViewSolution> solution;
  std::string problem;  // why there is none: eye inside the sphere, shares out of range, ...
};

SphereViewResult solveSphereView(const SphereViewProblem& problem);

}  // namespace glass::geometry
