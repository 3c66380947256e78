// The buffers of a window and their sizes in bits (glutGet's GLUT_WINDOW_*_SIZE), from its
// display mode as Mesa's visuals under X give them: a depth buffer with GLUT_DEPTH, and with
// GLUT_STENCIL too (depth and stencil come packed, 24 + 8 bits); a stencil buffer with
// GLUT_STENCIL; an accumulation buffer with GLUT_ACCUM. A buffer not asked for is absent
// (glassSetAncillaryBuffers): without GLUT_DEPTH the depth test does nothing, as on such a
// visual. The colour buffer has 8 bits of red, green and blue, and 8 alpha bits only with
// GLUT_ALPHA (glassSetAlphaBitplanes): without it GL_ALPHA_BITS is 0 and destination alpha reads
// 1, as on Mesa's visuals.
#pragma once

#include <GL/freeglut.h>

namespace glass::glut {

inline constexpr int kColorBits = 8;
inline constexpr int kDepthBits = 24;
inline constexpr int kStencilBits = 8;
inline constexpr int kAccumulationBits = 16;

struct AncillaryBits {
  int depth, stencil, accumulation;  // 0: no such buffer
};

// The colour buffer's alpha bits: GLUT_ALPHA's 8, or none.
inline int alphaBitsOf(unsigned displayMode) { return (displayMode & GLUT_ALPHA) != 0 ? kColorBits : 0; }

inline AncillaryBits ancillaryBitsOf(unsigned displayMode) {
  const bool stencil = (displayMode & GLUT_STENCIL) != 0;
  return {(displayMode & GLUT_DEPTH) != 0 || stencil ? kDepthBits : 0, stencil ? kStencilBits : 0,
          (displayMode & GLUT_ACCUM) != 0 ? kAccumulationBits : 0};
}

}  // namespace glass::glut
