// Conversion of integer colour and normal components to floating point (spec 2.14.9, table 2.9):
//   unsigned b-bit c -> c / (2^b - 1)          signed b-bit c -> (2c + 1) / (2^b - 1)
// so that the largest value maps to 1.0 and, for signed types, the smallest to -1.0.
// Vertex and texture coordinates are not normalized: they convert as plain numbers.
#pragma once

#include <GL/gl.h>

#include <cstring>

namespace glass::gl {

inline float normalizedToFloat(GLubyte c) { return static_cast<float>(c) / 255.0f; }
inline float normalizedToFloat(GLushort c) { return static_cast<float>(c) / 65535.0f; }
inline float normalizedToFloat(GLuint c) { return static_cast<float>(c / 4294967295.0); }
inline float normalizedToFloat(GLbyte c) { return (2.0f * c + 1.0f) / 255.0f; }
inline float normalizedToFloat(GLshort c) { return (2.0f * c + 1.0f) / 65535.0f; }
inline float normalizedToFloat(GLint c) { return static_cast<float>((2.0 * c + 1.0) / 4294967295.0); }
inline float normalizedToFloat(GLfloat c) { return c; }
inline float normalizedToFloat(GLdouble c) { return static_cast<float>(c); }

// A value of type T at p, which need not be aligned for T (client arrays may have any stride).
template <typename T>
T loadUnaligned(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

// An array component of type T as glass reads it (spec 2.8): normalized by table 2.9 for colours
// and normals, converted as a number otherwise (floats and doubles are taken as they are).
template <typename T>
float arrayComponentToFloat(T c, bool normalized) {
  return normalized ? normalizedToFloat(c) : static_cast<float>(c);
}

}  // namespace glass::gl
