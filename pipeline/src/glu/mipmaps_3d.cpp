// gluBuild3DMipmaps and gluBuild3DMipmapLevels (GLU 1.3, section 3.2). The arguments are checked
// as GLU checks them (GLU_INVALID_VALUE for a size below 1 or levels out of order,
// GLU_INVALID_ENUM for a target other than GL_TEXTURE_3D or an unknown format or type).
//
// gluBuild3DMipmaps loads level 0 with GL_GENERATE_MIPMAP on for the bound texture (and restores
// the setting after), so the GL builds every smaller level with its 2 x 2 x 2 box filter: the
// chain GLU's own 3D box filter makes, up to its rounding (SGI's halves in float; glass's
// generation rounds each average to the texel format). GLU's scaling of sizes that are not powers
// of two to the nearest power is not done: such an image is loaded as it is.
// gluBuild3DMipmapLevels loads the given level only.
#include <GL/gl.h>
#include <GL/glu.h>

namespace {

bool isPixelFormat(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX: case GL_DEPTH_COMPONENT: case GL_RED: case GL_GREEN: case GL_BLUE:
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RGB: case GL_BGR:
    case GL_RGBA: case GL_BGRA:
      return true;
    default: return false;
  }
}

bool isPixelType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
      return true;
    default: return false;
  }
}

GLint check3DArguments(GLenum target, GLsizei width, GLsizei height, GLsizei depth,
                       GLenum format, GLenum type) {
  if (width < 1 || height < 1 || depth < 1) return GLU_INVALID_VALUE;
  if (target != GL_TEXTURE_3D || !isPixelFormat(format) || !isPixelType(type)) {
    return GLU_INVALID_ENUM;
  }
  return 0;
}

}  // namespace

extern "C" {

GLint GLAPIENTRY gluBuild3DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                   GLsizei height, GLsizei depth, GLenum format, GLenum type,
                                   const void* data) {
  if (const GLint error = check3DArguments(target, width, height, depth, format, type)) {
    return error;
  }
  GLint generate = GL_FALSE;
  glGetTexParameteriv(target, GL_GENERATE_MIPMAP, &generate);
  glTexParameteri(target, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage3D(target, 0, internalFormat, width, height, depth, 0, format, type, data);
  glTexParameteri(target, GL_GENERATE_MIPMAP, generate);
  return 0;
}

GLint GLAPIENTRY gluBuild3DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                        GLsizei height, GLsizei depth, GLenum format,
                                        GLenum type, GLint level, GLint base, GLint max,
                                        const void* data) {
  if (const GLint error = check3DArguments(target, width, height, depth, format, type)) {
    return error;
  }
  if (base < 0 || base < level || max < base) return GLU_INVALID_VALUE;
  glTexImage3D(target, level, internalFormat, width, height, depth, 0, format, type, data);
  return 0;
}

}  // extern "C"
