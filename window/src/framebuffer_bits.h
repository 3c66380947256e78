// The buffers of a window and their sizes in bits (glutGet's GLUT_WINDOW_*_SIZE), from its
// display mode as Mesa's visuals under X give them: a depth buffer with GLUT_DEPTH, and with
// GLUT_STENCIL too (depth and stencil come packed, 24 + 8 bits); a stencil buffer with
// GLUT_STENCIL; an accumulation buffer with GLUT_ACCUM. A buffer not asked for is absent
// (glassSetAncillaryBuffers): without GLUT_DEPTH the depth test does nothing, as on such a
// visual. The colour buffer is always RGBA8 (glass has no framebuffer without alpha).
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

inline AncillaryBits ancillaryBitsOf(unsigned displayMode) {
  const bool stencil = (displayMode & GLUT_STENCIL) != 0;
  return {(displayMode & GLUT_DEPTH) != 0 || stencil ? kDepthBits : 0, stencil ? kStencilBits : 0,
          (displayMode & GLUT_ACCUM) != 0 ? kAccumulationBits : 0};
}

}  // namespace glass::glut
