// The normal of a triangle and its orientation (the study guide's exam, question 2):
//   n = (A1 - A0) x (A2 - A0),
// the normal of the plane through A0, A1, A2, whose equation is n . X = n . A0. Its direction
// tells the triangle's orientation: seen from the side n points to (from a point P with
// n . (P - A0) > 0), the vertices A0, A1, A2 run counter-clockwise, so that side is the front
// face under GL's default glFrontFace(GL_CCW); listing the vertices in the other order turns n
// round and makes the other side the front. The right-hand rule: curl the fingers of the right
// hand along A0 -> A1 -> A2 and the thumb points along n.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

namespace glass::geometry {

struct TriangleNormal {
  glm::dvec3 normal;      // (A1 - A0) x (A2 - A0), twice the triangle's area long
  glm::dvec3 unitNormal;  // normal / |normal|
  double area = 0.0;      // |normal| / 2
  double planeOffset = 0.0;  // n . A0, so the plane is n . X = planeOffset
};

// Empty for a degenerate triangle (collinear vertices).
std::optional<TriangleNormal> triangleNormal(const glm::dvec3& a0, const glm::dvec3& a1,
                                             const glm::dvec3& a2);

}  // namespace glass::geometry
