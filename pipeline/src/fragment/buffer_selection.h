// glDrawBuffer and glReadBuffer (spec 4.2.1, 4.3.2) on glass's framebuffer, which has one colour
// buffer: single-buffered, no stereo, no auxiliary buffers.
//
// The buffer names that denote the front-left colour buffer select it; GL_NONE selects none; the
// names of buffers a single-buffered mono framebuffer lacks are GL_INVALID_OPERATION. glass takes
// GL_BACK and GL_BACK_LEFT (and GL_FRONT_AND_BACK, GL_LEFT) as the one colour buffer, because Mesa
// does so in its off-screen contexts: a double-buffered program's glDrawBuffer(GL_BACK) or
// glReadBuffer(GL_BACK) then draws and reads the picture it means, on both.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// GL_NO_ERROR when `buffer` may be selected for drawing (glDrawBuffer) or reading
// (glReadBuffer), else the error the call sets.
GLenum drawBufferError(GLenum buffer);
GLenum readBufferError(GLenum buffer);

// False when glDrawBuffer(GL_NONE) is in effect: fragments then change no colour (depth and
// stencil are still written) and glClear leaves the colour buffer alone.
inline bool drawsColor(GLenum drawBuffer) { return drawBuffer != GL_NONE; }

// False when glReadBuffer(GL_NONE) is in effect: glReadPixels, glCopyPixels and the texture
// copies of colour then set GL_INVALID_OPERATION.
inline bool readsColor(GLenum readBuffer) { return readBuffer != GL_NONE; }

}  // namespace glass::gl
