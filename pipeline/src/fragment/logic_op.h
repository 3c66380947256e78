// glLogicOp's sixteen operations (spec 4.1.10, table 4.2) on 8-bit colour components:
// s is the fragment's value, d the colour buffer's.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glass::gl {

inline bool isLogicOp(GLenum op) { return op >= GL_CLEAR && op <= GL_SET; }

inline uint8_t applyLogicOp(GLenum op, uint8_t s, uint8_t d) {
  unsigned r;
  switch (op) {
    case GL_CLEAR: r = 0; break;
    case GL_AND: r = s & d; break;
    case GL_AND_REVERSE: r = s & ~d; break;
    case GL_COPY: r = s; break;
    case GL_AND_INVERTED: r = ~s & d; break;
    case GL_NOOP: r = d; break;
    case GL_XOR: r = s ^ d; break;
    case GL_OR: r = s | d; break;
    case GL_NOR: r = ~(s | d); break;
    case GL_EQUIV: r = ~(s ^ d); break;
    case GL_INVERT: r = ~d; break;
    case GL_OR_REVERSE: r = s | ~d; break;
    case GL_COPY_INVERTED: r = ~s; break;
    case GL_OR_INVERTED: r = ~s | d; break;
    case GL_NAND: r = ~(s & d); break;
    default: r = 0xFF; break;  // GL_SET
  }
  return static_cast<uint8_t>(r);
}

}  // namespace glass::gl
