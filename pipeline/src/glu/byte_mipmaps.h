// The fast path of GLU's 2D mipmap builders (core/fast_paths.h) for images of unsigned bytes,
// the case of nearly every program: the levels are halved on the bytes themselves, in a buffer
// reused from level to level, instead of as one double per element. GLU's average of unsigned
// bytes is integer arithmetic, (a + b + c + d + 2) / 4, or (a + b) / 2 along an axis already 1
// texel long, which the reference (halveImage on raw values held as doubles) computes exactly
// too, so the levels handed to glTexImage2D are the same bytes: the test glu_mipmaps.fast_paths
// runs the builders with the fast paths on and off, and glu_mipmaps compares them with libGLU.
#pragma once

#include <GL/gl.h>

namespace glass::glu {

// What loadTwoDimensionalLevels does for the client image `data` (read with the GL_UNPACK_*
// layout) of type GL_UNSIGNED_BYTE, taken as level `level` of `width` x `height` texels: each
// level to `max` halves the one before, and those from `base` on are loaded.
void loadByteLevels(GLenum target, GLint internalFormat, int width, int height, GLenum format, const void* data,
                    GLint level, GLint base, GLint max);

}  // namespace glass::glu
