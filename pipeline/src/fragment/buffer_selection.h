// glDrawBuffer and glReadBuffer (spec 4.2.1, 4.3.2) on glass's framebuffer, which has one colour
// buffer (single-buffered: off-screen and OSMesa contexts, GLUT_SINGLE windows) or a front and a
// back one (double-buffered: glassSetDoubleBuffered, GLUT_DOUBLE windows). No stereo, no
// auxiliary buffers.
//
// The names of the front-left and back-left buffers select them; GL_NONE selects none; the names
// of buffers glass's framebuffers lack are GL_INVALID_OPERATION. A single-buffered framebuffer
// takes GL_BACK and GL_BACK_LEFT (and GL_FRONT_AND_BACK, GL_LEFT) as its one colour buffer,
// because Mesa does so in its off-screen contexts and its single-buffered windows: a
// double-buffered program's glDrawBuffer(GL_BACK) or glReadBuffer(GL_BACK) then draws and reads
// the picture it means, on both.
//
// In a double-buffered framebuffer the back buffer is the framebuffer's colour buffer 0 and the
// front its buffer 1 (raster::Framebuffer::selectColorBuffer). Fragments go to the selected
// buffer (colorAt), chosen when glDrawBuffer changes (selectDrawBuffer); GL_FRONT_AND_BACK and
// GL_LEFT select the back buffer and write each fragment into the front one as well
// (writesBothBuffers: each buffer blended, masked and logic-op'd with its own pixels). A read
// selects the read buffer for its duration (ReadBufferSelection).
#pragma once

#include <GL/gl.h>

#include <cstdint>

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

inline constexpr int kBackColorBuffer = 0, kFrontColorBuffer = 1;

bool isDoubleBuffered(const Context& ctx);

// Selects the framebuffer's colour buffer `index` for colorAt, after finishing the queued drawing
// when that changes which.
void selectColorBuffer(Context& ctx, int index);

// Gives the context a front and a back colour buffer (the front a copy of the colour buffer it
// had) or only one, and sets the draw and read buffers to their initial values for it: GL_BACK
// with two, GL_FRONT with one (spec 4.2.1, 4.3.2). Throws std::bad_alloc, changing nothing.
void setDoubleBuffered(Context& ctx, bool doubleBuffered);

// The initial draw and read buffer of the context's framebuffer (glassResetContext).
GLenum initialColorBuffer(const Context& ctx);

// Selects in the framebuffer the colour buffer that glDrawBuffer's value draws into (the back
// one for both), after finishing the queued drawing when that changes which: after glDrawBuffer,
// glPopAttrib and a new framebuffer.
void selectDrawBuffer(Context& ctx);

// Whether fragments are also written into the front buffer (GL_FRONT_AND_BACK or GL_LEFT in a
// double-buffered framebuffer), through raster::Framebuffer::otherColorAt.
bool writesBothBuffers(const Context& ctx);

// Calls writeOne() once for each colour buffer that writes of the draw buffer go to, that buffer
// selected: for code that writes colour without fragments of a draw (glClear, glAccum's
// GL_RETURN). Queued drawing is finished before each change of the selected buffer.
template <typename WriteOne>
void forEachDrawnColorBuffer(Context& ctx, WriteOne writeOne);

// For the duration of a read of colour (glReadPixels, glCopyPixels' read, glCopyTexImage,
// glAccum's GL_LOAD and GL_ACCUM, ...): colorAt addresses the buffer glReadBuffer names. Queued
// drawing is finished first when that changes the selected buffer, and the draw buffer is
// selected again at the end.
class ReadBufferSelection {
 public:
  explicit ReadBufferSelection(Context& ctx);
  ~ReadBufferSelection();
  ReadBufferSelection(const ReadBufferSelection&) = delete;
  ReadBufferSelection& operator=(const ReadBufferSelection&) = delete;

 private:
  Context& ctx_;
};

// glassSwapBuffers: the queued drawing finished, the back buffer's pixels copied into the front
// (the back keeps them, as Mesa's swap does). Nothing in a single-buffered framebuffer.
void swapColorBuffers(Context& ctx);

// The pixels of the front buffer (the one colour buffer of a single-buffered framebuffer) and of
// the back buffer (the same), as raster::Framebuffer::colorBufferPixels gives them.
const uint8_t* frontBufferPixels(const Context& ctx);
const uint8_t* backBufferPixels(const Context& ctx);

}  // namespace glass::gl

#include "fragment/buffer_selection-inl.h"
