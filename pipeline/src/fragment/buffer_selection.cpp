#include "fragment/buffer_selection.h"

namespace glass::gl {

namespace {

// Table 4.4: the buffers a name denotes. glass's framebuffer has only the front-left buffer
// (Mesa's off-screen framebuffer treats the back-left names as that same buffer, see the header).
bool namesTheColorBuffer(GLenum buffer) {
  switch (buffer) {
    case GL_FRONT: case GL_BACK: case GL_LEFT: case GL_FRONT_LEFT: case GL_BACK_LEFT:
    case GL_FRONT_AND_BACK:
      return true;
    default: return false;
  }
}

// Names of buffers that exist in some framebuffer, but not in glass's: selecting them is
// GL_INVALID_OPERATION (spec 4.2.1), not GL_INVALID_ENUM.
bool namesAMissingBuffer(GLenum buffer) {
  switch (buffer) {
    case GL_RIGHT: case GL_FRONT_RIGHT: case GL_BACK_RIGHT:
      return true;
    default: return buffer >= GL_AUX0 && buffer <= GL_AUX3;
  }
}

}  // namespace

GLenum drawBufferError(GLenum buffer) {
  if (buffer == GL_NONE || namesTheColorBuffer(buffer)) return GL_NO_ERROR;
  return namesAMissingBuffer(buffer) ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

// Spec 4.3.2 lists neither GL_FRONT_AND_BACK (two buffers) nor GL_NONE for glReadBuffer; Mesa
// accepts both on its off-screen framebuffer (GL 3.0 added GL_NONE), and so does glass.
GLenum readBufferError(GLenum buffer) { return drawBufferError(buffer); }

}  // namespace glass::gl
