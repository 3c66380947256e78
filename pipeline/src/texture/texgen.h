// Texture coordinate generation (glTexGen, OpenGL 1.5 specification, section 2.11.4).
//   OBJECT_LINEAR  g = p1 xo + p2 yo + p3 zo + p4 wo        (the plane as given)
//   EYE_LINEAR     g = p1' xe + p2' ye + p3' ze + p4' we,   (p1' p2' p3' p4') = (p1 p2 p3 p4) M^-1
//                  with M the modelview matrix when glTexGen was called (the plane is stored
//                  transformed, so the vertex stage only takes a dot product)
//   SPHERE_MAP     u = the unit vector from the eye to the vertex, n' = the eye-space normal,
//                  r = u - 2 n' (n' . u), m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),
//                  s = rx / m + 1/2, t = ry / m + 1/2  (s and t only)
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

// The sphere-map coordinates (s, t) of a vertex.
void sphereMapCoordinates(const float eyePosition[4], const float eyeNormal[3], float* s, float* t);

// Generates coordinate `index` (0 = s .. 3 = q) for one vertex; sphereMap holds the vertex's
// sphere-map (s, t) when any coordinate uses SPHERE_MAP.
float generateTexCoordinate(const TexGenCoordinate& coordinate, int index,
                            const float objectPosition[4], const float eyePosition[4],
                            const float sphereMap[2]);

// The eye plane of glTexGen(GL_EYE_PLANE): p' = p M^-1, with M column-major as GL stores it.
// A singular M leaves the plane as given.
void transformEyePlane(const float plane[4], const float modelview[16], float out[4]);

}  // namespace glass::gl
