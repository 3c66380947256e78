// Which ancillary buffers a context's framebuffer has. OpenGL 1.5, chapter 4: a framebuffer may
// lack a depth, stencil or accumulation buffer (an OSMesa context asks for each by its bits; one
// of 0 bits is absent). glass keeps the storage either way (docs/osmesa.md); what a missing
// buffer changes is what the specification says:
//   - GL_DEPTH_BITS, GL_STENCIL_BITS, GL_ACCUM_*_BITS report 0 (table 6.34);
//   - the depth and stencil tests act as if they pass and write nothing (4.1.5, 4.1.4);
//   - glClear leaves it alone (4.2.3);
//   - glAccum is GL_INVALID_OPERATION (4.2.4), and so are glReadPixels and glCopyPixels of its
//     data (4.3.2, 4.3.3) and glCopyTexImage into a depth texture without a depth buffer
//     (ARB_depth_texture).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

struct AncillaryBuffers {
  bool depth = true;
  bool stencil = true;
  bool accumulation = true;
};

// Whether reading pixels of `format` (glReadPixels) or `type` (glCopyPixels: GL_DEPTH,
// GL_STENCIL) finds the buffer they come from; colour always does.
bool hasBufferToRead(const Context& ctx, GLenum formatOrType);

// The depth and stencil tests as they act: enabled and with a buffer to test against.
bool depthTestActive(const Context& ctx);
bool stencilTestActive(const Context& ctx);

}  // namespace glass::gl
