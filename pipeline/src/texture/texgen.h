// Texture coordinate generation (glTexGen, OpenGL 1.5 specification, section 2.11.4).
//   OBJECT_LINEAR  g = p1 xo + p2 yo + p3 zo + p4 wo        (the plane as given)
//   EYE_LINEAR     g = p1' xe + p2' ye + p3' ze + p4' we,   (p1' p2' p3' p4') = (p1 p2 p3 p4) M^-1
//                  with M the modelview matrix when glTexGen was called (the plane is stored
//                  transformed, so the vertex stage only takes a dot product)
//   SPHERE_MAP     u = the unit vector from the eye to the vertex, n' = the eye-space normal,
//                  r = u - 2 n' (n' . u), m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),
//                  s = rx / m + 1/2, t = ry / m + 1/2  (s and t only)
//   REFLECTION_MAP (s, t, r) = (rx, ry, rz), the reflection vector above  (OpenGL 1.3; not q)
//   NORMAL_MAP     (s, t, r) = n', the eye-space normal                     (OpenGL 1.3; not q)
#pragma once

#include <GL/gl.h>

namespace glass::gl {

// The glTexGen state of one coordinate (s, t, r or q), table 6.15 defaults.
struct TexGenCoordinate {
  bool enabled = false;        // glEnable(GL_TEXTURE_GEN_S ...)
  GLenum mode = GL_EYE_LINEAR;
  float objectPlane[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  float eyePlane[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // stored as p M^-1
};

// The spec's defaults: s planes (1, 0, 0, 0), t planes (0, 1, 0, 0), r and q zero.
void setDefaultTexGenPlanes(TexGenCoordinate coordinates[4]);

// What the eye-space modes of a vertex generate: the sphere-map (s, t), the reflection vector
// and the eye-space normal.
struct EyeSpaceVectors {
  float sphereMap[2] = {0.0f, 0.0f};
  float reflection[3] = {0.0f, 0.0f, 0.0f};
  float normal[3] = {0.0f, 0.0f, 0.0f};
};

// The vectors of a vertex (u, r and m as above).
EyeSpaceVectors eyeSpaceVectors(const float eyePosition[4], const float eyeNormal[3]);

// Generates coordinate `index` (0 = s .. 3 = q) for one vertex; `vectors` holds the vertex's
// eye-space vectors when any coordinate uses SPHERE_MAP, REFLECTION_MAP or NORMAL_MAP.
float generateTexCoordinate(const TexGenCoordinate& coordinate, int index,
                            const float objectPosition[4], const float eyePosition[4],
                            const EyeSpaceVectors& vectors);

// True for the modes computed from eye-space vectors.
inline bool isEyeSpaceVectorMode(GLenum mode) {
  return mode == GL_SPHERE_MAP || mode == GL_REFLECTION_MAP || mode == GL_NORMAL_MAP;
}

// The eye plane of glTexGen(GL_EYE_PLANE): p' = p M^-1, with M column-major as GL stores it.
// A singular M leaves the plane as given.
void transformEyePlane(const float plane[4], const float modelview[16], float out[4]);

}  // namespace glass::gl
