// Texel addressing along one axis of a texture image (OpenGL 1.5 specification, 3.8.7 and
// 3.8.8): the texel coordinate u = s * size and the wrap modes, shared by the reference sampler
// (texture_sampler.cpp) and the prepared 2D sampler of the fragment kernels (sampler_2d.h), so
// that both compute every index the same way. The formulas (u, wrap()) are in texture_sampler.h.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace glass::gl {

// Texel coordinates far outside the image would overflow an int in floor(). The clamping modes
// only need u to stay outside the image, so it is clamped to [-1, size + 1]; the repeating modes
// give the same texel for u and for u reduced by a multiple of 2 * size (the period of
// MIRRORED_REPEAT), so large values are reduced.
inline float keepInIntRange(float u, int size, GLenum mode) {
  if (!(u == u)) return 0.0f;  // NaN
  if (mode != GL_REPEAT && mode != GL_MIRRORED_REPEAT)
    return std::clamp(u, -1.0f, static_cast<float>(size) + 1.0f);
  const float limit = 1048576.0f;  // 2^20, far beyond kMaxTextureSize
  if (u > -limit && u < limit) return u;
  if (!std::isfinite(u)) return 0.0f;
  const double period = 2.0 * size;
  double r = std::fmod(static_cast<double>(u), period);
  if (r < 0.0) r += period;
  return static_cast<float>(r);
}

inline int positiveModulo(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// wrap() of texture_sampler.h; `linear` selects the CLAMP variant for LINEAR filtering.
inline int wrapTexelIndex(int i, int size, GLenum mode, bool linear) {
  switch (mode) {
    case GL_REPEAT:
      // Power-of-two sizes (the usual case) wrap with a mask: the same result, no division.
      return (size & (size - 1)) == 0 ? (i & (size - 1)) : positiveModulo(i, size);
    case GL_MIRRORED_REPEAT: {
      const int a = positiveModulo(i, 2 * size) - size;
      const int mirrored = a >= 0 ? a : -(1 + a);
      return (size - 1) - mirrored;
    }
    case GL_CLAMP_TO_EDGE: return std::clamp(i, 0, size - 1);
    case GL_CLAMP_TO_BORDER: return std::clamp(i, -1, size);
    case GL_CLAMP: return linear ? std::clamp(i, -1, size) : std::clamp(i, 0, size - 1);
    default: return positiveModulo(i, size);
  }
}

// The pair wrap(i), wrap(i + 1) of LINEAR filtering. For REPEAT the second follows from the
// first without another division.
inline void wrapTexelPair(int i, int size, GLenum mode, int* i0, int* i1) {
  *i0 = wrapTexelIndex(i, size, mode, true);
  if (mode == GL_REPEAT) {
    *i1 = *i0 + 1 == size ? 0 : *i0 + 1;
  } else {
    *i1 = wrapTexelIndex(i + 1, size, mode, true);
  }
}

// The texel coordinate u = s * size of one axis; CLAMP clamps s to [0, 1] first.
inline float texelCoordinate(float s, int size, GLenum mode) {
  if (mode == GL_CLAMP) s = std::clamp(s, 0.0f, 1.0f);
  return keepInIntRange(s * static_cast<float>(size), size, mode);
}

// floor(u) as an int, for u in the range keepInIntRange leaves (|u| <= 2^21): the conversion
// truncates towards zero, which is one too high for a negative u with a fraction. Every int of
// that range is a float, so static_cast<float>(floorToInt(u)) is std::floor(u) (but for the sign
// of a zero, which no lookup sees: u - 1/2 is never -0).
inline int floorToInt(float u) {
  const int truncated = static_cast<int>(u);
  return static_cast<float>(truncated) > u ? truncated - 1 : truncated;
}

}  // namespace glass::gl
