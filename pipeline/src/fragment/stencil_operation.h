// glStencilOp's operations (spec 4.1.5), on an 8-bit stencil buffer.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glass::gl {

inline bool isStencilOperation(GLenum op) {
  switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR: case GL_INVERT:
    case GL_INCR_WRAP: case GL_DECR_WRAP:
      return true;
    default:
      return false;
  }
}

// The new stencil value before the write mask is applied. INCR and DECR saturate at 0 and 255;
// the _WRAP forms (GL 1.4) wrap around.
inline uint8_t applyStencilOperation(GLenum op, uint8_t value, uint8_t reference) {
  switch (op) {
    case GL_ZERO: return 0;
    case GL_REPLACE: return reference;
    case GL_INCR: return value == 255 ? 255 : static_cast<uint8_t>(value + 1);
    case GL_DECR: return value == 0 ? 0 : static_cast<uint8_t>(value - 1);
    case GL_INVERT: return static_cast<uint8_t>(~value);
    case GL_INCR_WRAP: return static_cast<uint8_t>(value + 1);
    case GL_DECR_WRAP: return static_cast<uint8_t>(value - 1);
    default: return value;  // GL_KEEP
  }
}

// Writes value through the stencil write mask (spec 4.2.2): only bits set in mask change.
inline void writeStencil(uint8_t& stored, uint8_t value, unsigned mask) {
  stored = static_cast<uint8_t>((stored & ~mask) | (value & mask));
}

}  // namespace glass::gl
