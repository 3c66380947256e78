#include "view/trackball.h"

#include <glass/geometry/rotation.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include "glass/geometry/portable_math.h"

namespace glass::cli::view {

glm::dvec3 trackballPoint(double x, double y, int width, int height) {
  const double half = std::max(1, std::min(width, height)) / 2.0;
  const double px = (x - width / 2.0) / half, py = (height / 2.0 - y) / half;
  const double d2 = px * px + py * py;
  // Inside the circle of radius 1/sqrt(2) the sphere z = sqrt(1 - d^2); outside it the sheet
  // z = 1 / (2 d), which meets the sphere there with the same height and slope.
  const double z = d2 <= 0.5 ? std::sqrt(1.0 - d2) : 0.5 / std::sqrt(d2);
  return {px, py, z};
}

geometry::Quaternion trackballDrag(double x0, double y0, double x1, double y1, int width, int height) {
  const glm::dvec3 from = glm::normalize(trackballPoint(x0, y0, width, height));
  const glm::dvec3 to = glm::normalize(trackballPoint(x1, y1, width, height));
  const glm::dvec3 axis = glm::cross(from, to);
  const double sine = glm::length(axis);
  if (!(sine > 1e-12)) return {};
  const double angle = portable::atan2(sine, glm::dot(from, to));
  return geometry::rotationQuaternion(axis / sine, angle);
}

geometry::Quaternion turnByDrag(const geometry::Quaternion& orientation, const geometry::Quaternion& dragInEye,
                                const glm::dvec3& eye, const glm::dvec3& centre, const glm::dvec3& up) {
  const glm::dvec3 back = glm::normalize(eye - centre);
  const glm::dvec3 right = glm::normalize(glm::cross(up, back));
  const glm::dvec3 trueUp = glm::cross(back, right);
  const glm::dvec3 v = dragInEye.imaginary();
  const geometry::Quaternion dragInWorld(dragInEye.w, v.x * right + v.y * trueUp + v.z * back);
  return geometry::normalized(dragInWorld * orientation);
}

} // namespace glass::cli::view
