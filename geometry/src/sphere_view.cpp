#include "glass/geometry/sphere_view.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

SphereViewResult solveSphereView(const SphereViewProblem& problem) {
  SphereViewResult result;
  const double r = problem.radius;
  if (!(r > 0.0)) {
    result.problem = "the radius must be positive";
    return result;
  }
  if (!(problem.heightShare > 0.0 && problem.heightShare <= 1.0) ||
      !(problem.widthShare > 0.0 && problem.widthShare <= 1.0)) {
    result.problem = "the shares of the window's height and width must lie in (0, 1]";
    return result;
  }
  if (!(problem.visibleFraction > 0.0 && problem.visibleFraction <= 0.5)) {
    result.problem =
        "the visible part must lie in (0, 1/2]: beyond one half, the near plane cuts in front of "
        "the centre and the front of the sphere hides part of what lies behind the plane";
    return result;
  }
  const glm::dvec3 toCenter = problem.center - problem.eye;
  const double d = glm::length(toCenter);
  if (!(d > r)) {
    result.problem = "the eye must be outside the sphere";
    return result;
  }
  const double crossLength = glm::length(glm::cross(toCenter, problem.up));
  if (!(crossLength > 1e-12 * d * glm::length(problem.up))) {
    result.problem = "the up vector must not be parallel to the line of sight";
    return result;
  }

  SphereViewSolution s;
  s.eye = problem.eye;
  s.center = problem.center;
  s.up = problem.up;
  s.distance = d;
  s.planeOffset = r * (1.0 - 2.0 * problem.visibleFraction);
  s.rimRadius = std::sqrt(r * r - s.planeOffset * s.planeOffset);
  s.zNear = d + s.planeOffset;
  s.backDistance = d + r;
  s.zFar = d + 2.0 * r;
  s.fovyDegrees = 2.0 * portable::atan(s.rimRadius / (problem.heightShare * s.zNear)) * (180.0 / std::numbers::pi);
  s.aspect = problem.heightShare / problem.widthShare;
  result.solution = s;
  return result;
}

}  // namespace glass::geometry
