// Compressed texture images (OpenGL 1.3, spec 3.8.3, 3.8.4, 6.1.4). glass stores every texture
// uncompressed and knows no specific compressed format: GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0
// (texture/compressed_textures.h). The generic compressed internal formats (GL_COMPRESSED_RGB,
// ...) are accepted by glTexImage, which stores them uncompressed as the specification allows.
// So the commands that take compressed data always fail with the error the specification gives
// for an internal format or format that is not a supported compressed one: GL_INVALID_ENUM.
// glGetCompressedTexImage fails with GL_INVALID_OPERATION, since no image is compressed.
#include <GL/gl.h>

#include "core/context.h"
#include "core/state_value.h"
#include "lists/command_recording.h"
#include "texture/compressed_textures.h"

using glass::gl::Context;

namespace glass::gl {

bool queryCompressedTextureState(const Context&, GLenum pname, StateValue& v) {
  switch (pname) {
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: v.setIntegers({0}); return true;
    case GL_COMPRESSED_TEXTURE_FORMATS: v.setIntegers({}); return true;
    default: return false;
  }
}

}  // namespace glass::gl

namespace {

// Compiled into display lists like the glTexImage they parallel; the error appears when the
// command executes.
void rejectCompressedImage() {
  glass::gl::compileOrExecute([](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    glass::gl::recordError(ctx, GL_INVALID_ENUM);
  });
}

}  // namespace

extern "C" {

void glCompressedTexImage1D(GLenum, GLint, GLenum, GLsizei, GLint, GLsizei, const GLvoid*) {
  rejectCompressedImage();
}
void glCompressedTexImage2D(GLenum, GLint, GLenum, GLsizei, GLsizei, GLint, GLsizei,
                            const GLvoid*) {
  rejectCompressedImage();
}
void glCompressedTexImage3D(GLenum, GLint, GLenum, GLsizei, GLsizei, GLsizei, GLint, GLsizei,
                            const GLvoid*) {
  rejectCompressedImage();
}
void glCompressedTexSubImage1D(GLenum, GLint, GLint, GLsizei, GLenum, GLsizei, const GLvoid*) {
  rejectCompressedImage();
}
void glCompressedTexSubImage2D(GLenum, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLsizei,
                               const GLvoid*) {
  rejectCompressedImage();
}
void glCompressedTexSubImage3D(GLenum, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei,
                               GLenum, GLsizei, const GLvoid*) {
  rejectCompressedImage();
}

// Spec 6.1.4: a target that is not a texture image target is GL_INVALID_ENUM, a negative level
// GL_INVALID_VALUE, an image that is not compressed GL_INVALID_OPERATION. Never compiled.
void glGetCompressedTexImage(GLenum target, GLint level, GLvoid*) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) {
      return glass::gl::recordError(ctx, GL_INVALID_ENUM);
    }
    if (level < 0) return glass::gl::recordError(ctx, GL_INVALID_VALUE);
    glass::gl::recordError(ctx, GL_INVALID_OPERATION);
  });
}

}  // extern "C"
