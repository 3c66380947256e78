// Three-dimensional textures (OpenGL 1.2, spec 3.8.1): glTexImage3D, glTexSubImage3D and
// glCopyTexSubImage3D. glass has 1D and 2D textures only; GL_TEXTURE_3D and
// GL_PROXY_TEXTURE_3D are not targets it knows, so each command sets GL_INVALID_ENUM, the error
// the specification gives for a target that is not accepted, and changes nothing (the README
// lists this among what glass does not do). glEnable(GL_TEXTURE_3D) is GL_INVALID_ENUM likewise.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::Context;

namespace {

// Compiled into display lists like glTexImage2D (its proxy form is not, spec 5.4, but it fails
// the same way either way).
void rejectTexture3D() {
  glass::gl::compileOrExecute([](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    glass::gl::recordError(ctx, GL_INVALID_ENUM);
  });
}

}  // namespace

extern "C" {

void glTexImage3D(GLenum, GLint, GLint, GLsizei, GLsizei, GLsizei, GLint, GLenum, GLenum,
                  const GLvoid*) {
  rejectTexture3D();
}
void glTexSubImage3D(GLenum, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei, GLenum,
                     GLenum, const GLvoid*) {
  rejectTexture3D();
}
void glCopyTexSubImage3D(GLenum, GLint, GLint, GLint, GLint, GLint, GLint, GLsizei, GLsizei) {
  rejectTexture3D();
}

}  // extern "C"
