#include "texture/texgen.h"

#include <cmath>

#include <glm/glm.hpp>

namespace glass::gl {

void setDefaultTexGenPlanes(TexGenCoordinate coordinates[4]) {
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 4; ++k) {
      const float v = (i == k && i < 2) ? 1.0f : 0.0f;
      coordinates[i].objectPlane[k] = v;
      coordinates[i].eyePlane[k] = v;
    }
  }
}

EyeSpaceVectors eyeSpaceVectors(const float eyePosition[4], const float eyeNormal[3]) {
  EyeSpaceVectors v;
  // u: the direction from the eye (the origin of eye space) to the vertex. A vertex at the eye
  // has no direction; u = 0 then gives r = 0 and (s, t) = (1/2, 1/2).
  float u[3] = {eyePosition[0], eyePosition[1], eyePosition[2]};
  const float length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (length > 0.0f)
    for (float& c : u) c /= length;
  const float nDotU = eyeNormal[0] * u[0] + eyeNormal[1] * u[1] + eyeNormal[2] * u[2];
  float* r = v.reflection;
  for (int k = 0; k < 3; ++k) {
    r[k] = u[k] - 2.0f * eyeNormal[k] * nDotU;
    v.normal[k] = eyeNormal[k];
  }
  const float m = 2.0f * std::sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0f) * (r[2] + 1.0f));
  // m = 0 only for r = (0, 0, -1), the reflection straight away from the viewer: the edge of the
  // sphere map, where any point of the rim is right.
  if (m > 0.0f) {
    v.sphereMap[0] = r[0] / m + 0.5f;
    v.sphereMap[1] = r[1] / m + 0.5f;
  } else {
    v.sphereMap[0] = 0.5f;
    v.sphereMap[1] = 0.5f;
  }
  return v;
}

float generateTexCoordinate(const TexGenCoordinate& coordinate, int index,
                            const float objectPosition[4], const float eyePosition[4],
                            const EyeSpaceVectors& vectors) {
  switch (coordinate.mode) {
    case GL_OBJECT_LINEAR: {
      const float* p = coordinate.objectPlane;
      return p[0] * objectPosition[0] + p[1] * objectPosition[1] + p[2] * objectPosition[2] +
             p[3] * objectPosition[3];
    }
    case GL_EYE_LINEAR: {
      const float* p = coordinate.eyePlane;
      return p[0] * eyePosition[0] + p[1] * eyePosition[1] + p[2] * eyePosition[2] +
             p[3] * eyePosition[3];
    }
    case GL_SPHERE_MAP:
      return index < 2 ? vectors.sphereMap[index] : 0.0f;
    case GL_REFLECTION_MAP:
      return index < 3 ? vectors.reflection[index] : 0.0f;
    case GL_NORMAL_MAP:
      return index < 3 ? vectors.normal[index] : 0.0f;
    default:
      return 0.0f;
  }
}

void transformEyePlane(const float plane[4], const float modelview[16], float out[4]) {
  glm::dmat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = modelview[c * 4 + r];
  const double det = glm::determinant(m);
  if (det == 0.0 || !std::isfinite(det)) {
    for (int k = 0; k < 4; ++k) out[k] = plane[k];
    return;
  }
  const glm::dmat4 inverse = glm::inverse(m);
  const glm::dvec4 p(plane[0], plane[1], plane[2], plane[3]);
  // A row vector times a matrix: glm's v * M is exactly that.
  const glm::dvec4 q = p * inverse;
  for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(q[k]);
}

}  // namespace glass::gl
