// The extension names of core commands (<GL/glext.h>): each function is the core command it
// became, called with the same arguments. The extensions' specifications define the behaviour
// of the core sections that absorbed them (OpenGL 1.4 specification, appendices F-J), so there is
// nothing to adapt; only glTexImage3DEXT takes its internal format as a GLenum where
// glTexImage3D takes a GLint, with the same values.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

extern "C" {

// GL_ARB_transpose_matrix
void glLoadTransposeMatrixfARB(const GLfloat* m) { glLoadTransposeMatrixf(m); }
void glLoadTransposeMatrixdARB(const GLdouble* m) { glLoadTransposeMatrixd(m); }
void glMultTransposeMatrixfARB(const GLfloat* m) { glMultTransposeMatrixf(m); }
void glMultTransposeMatrixdARB(const GLdouble* m) { glMultTransposeMatrixd(m); }

// GL_ARB_multisample
void glSampleCoverageARB(GLfloat value, GLboolean invert) { glSampleCoverage(value, invert); }

// GL_ARB_texture_compression
void glCompressedTexImage3DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                               GLsizei height, GLsizei depth, GLint border, GLsizei imageSize,
                               const void* data) {
  glCompressedTexImage3D(target, level, internalformat, width, height, depth, border, imageSize,
                         data);
}
void glCompressedTexImage2DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                               GLsizei height, GLint border, GLsizei imageSize, const void* data) {
  glCompressedTexImage2D(target, level, internalformat, width, height, border, imageSize, data);
}
void glCompressedTexImage1DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                               GLint border, GLsizei imageSize, const void* data) {
  glCompressedTexImage1D(target, level, internalformat, width, border, imageSize, data);
}
void glCompressedTexSubImage3DARB(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                  GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                  GLenum format, GLsizei imageSize, const void* data) {
  glCompressedTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                            imageSize, data);
}
void glCompressedTexSubImage2DARB(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                  GLsizei width, GLsizei height, GLenum format, GLsizei imageSize,
                                  const void* data) {
  glCompressedTexSubImage2D(target, level, xoffset, yoffset, width, height, format, imageSize,
                            data);
}
void glCompressedTexSubImage1DARB(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                  GLenum format, GLsizei imageSize, const void* data) {
  glCompressedTexSubImage1D(target, level, xoffset, width, format, imageSize, data);
}
void glGetCompressedTexImageARB(GLenum target, GLint level, void* img) {
  glGetCompressedTexImage(target, level, img);
}

// GL_ARB_point_parameters
void glPointParameterfARB(GLenum pname, GLfloat param) { glPointParameterf(pname, param); }
void glPointParameterfvARB(GLenum pname, const GLfloat* params) {
  glPointParameterfv(pname, params);
}

// GL_ARB_window_pos
void glWindowPos2dARB(GLdouble x, GLdouble y) { glWindowPos2d(x, y); }
void glWindowPos2dvARB(const GLdouble* v) { glWindowPos2dv(v); }
void glWindowPos2fARB(GLfloat x, GLfloat y) { glWindowPos2f(x, y); }
void glWindowPos2fvARB(const GLfloat* v) { glWindowPos2fv(v); }
void glWindowPos2iARB(GLint x, GLint y) { glWindowPos2i(x, y); }
void glWindowPos2ivARB(const GLint* v) { glWindowPos2iv(v); }
void glWindowPos2sARB(GLshort x, GLshort y) { glWindowPos2s(x, y); }
void glWindowPos2svARB(const GLshort* v) { glWindowPos2sv(v); }
void glWindowPos3dARB(GLdouble x, GLdouble y, GLdouble z) { glWindowPos3d(x, y, z); }
void glWindowPos3dvARB(const GLdouble* v) { glWindowPos3dv(v); }
void glWindowPos3fARB(GLfloat x, GLfloat y, GLfloat z) { glWindowPos3f(x, y, z); }
void glWindowPos3fvARB(const GLfloat* v) { glWindowPos3fv(v); }
void glWindowPos3iARB(GLint x, GLint y, GLint z) { glWindowPos3i(x, y, z); }
void glWindowPos3ivARB(const GLint* v) { glWindowPos3iv(v); }
void glWindowPos3sARB(GLshort x, GLshort y, GLshort z) { glWindowPos3s(x, y, z); }
void glWindowPos3svARB(const GLshort* v) { glWindowPos3sv(v); }

// GL_EXT_blend_color
void glBlendColorEXT(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  glBlendColor(red, green, blue, alpha);
}

// GL_EXT_blend_func_separate
void glBlendFuncSeparateEXT(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha,
                            GLenum dfactorAlpha) {
  glBlendFuncSeparate(sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha);
}

// GL_EXT_blend_minmax
void glBlendEquationEXT(GLenum mode) { glBlendEquation(mode); }

// GL_EXT_copy_texture
void glCopyTexImage1DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                         GLsizei width, GLint border) {
  glCopyTexImage1D(target, level, internalformat, x, y, width, border);
}
void glCopyTexImage2DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                         GLsizei width, GLsizei height, GLint border) {
  glCopyTexImage2D(target, level, internalformat, x, y, width, height, border);
}
void glCopyTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                            GLsizei width) {
  glCopyTexSubImage1D(target, level, xoffset, x, y, width);
}
void glCopyTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                            GLint y, GLsizei width, GLsizei height) {
  glCopyTexSubImage2D(target, level, xoffset, yoffset, x, y, width, height);
}
void glCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                            GLint x, GLint y, GLsizei width, GLsizei height) {
  glCopyTexSubImage3D(target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

// GL_EXT_draw_range_elements
void glDrawRangeElementsEXT(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                            const void* indices) {
  glDrawRangeElements(mode, start, end, count, type, indices);
}

// GL_EXT_fog_coord
void glFogCoordfEXT(GLfloat coord) { glFogCoordf(coord); }
void glFogCoordfvEXT(const GLfloat* coord) { glFogCoordfv(coord); }
void glFogCoorddEXT(GLdouble coord) { glFogCoordd(coord); }
void glFogCoorddvEXT(const GLdouble* coord) { glFogCoorddv(coord); }
void glFogCoordPointerEXT(GLenum type, GLsizei stride, const void* pointer) {
  glFogCoordPointer(type, stride, pointer);
}

// GL_EXT_multi_draw_arrays
void glMultiDrawArraysEXT(GLenum mode, const GLint* first, const GLsizei* count,
                          GLsizei primcount) {
  glMultiDrawArrays(mode, first, count, primcount);
}
void glMultiDrawElementsEXT(GLenum mode, const GLsizei* count, GLenum type,
                            const void* const* indices, GLsizei primcount) {
  glMultiDrawElements(mode, count, type, indices, primcount);
}

// GL_EXT_point_parameters
void glPointParameterfEXT(GLenum pname, GLfloat param) { glPointParameterf(pname, param); }
void glPointParameterfvEXT(GLenum pname, const GLfloat* params) {
  glPointParameterfv(pname, params);
}

// GL_EXT_secondary_color
void glSecondaryColor3bEXT(GLbyte red, GLbyte green, GLbyte blue) {
  glSecondaryColor3b(red, green, blue);
}
void glSecondaryColor3bvEXT(const GLbyte* v) { glSecondaryColor3bv(v); }
void glSecondaryColor3dEXT(GLdouble red, GLdouble green, GLdouble blue) {
  glSecondaryColor3d(red, green, blue);
}
void glSecondaryColor3dvEXT(const GLdouble* v) { glSecondaryColor3dv(v); }
void glSecondaryColor3fEXT(GLfloat red, GLfloat green, GLfloat blue) {
  glSecondaryColor3f(red, green, blue);
}
void glSecondaryColor3fvEXT(const GLfloat* v) { glSecondaryColor3fv(v); }
void glSecondaryColor3iEXT(GLint red, GLint green, GLint blue) {
  glSecondaryColor3i(red, green, blue);
}
void glSecondaryColor3ivEXT(const GLint* v) { glSecondaryColor3iv(v); }
void glSecondaryColor3sEXT(GLshort red, GLshort green, GLshort blue) {
  glSecondaryColor3s(red, green, blue);
}
void glSecondaryColor3svEXT(const GLshort* v) { glSecondaryColor3sv(v); }
void glSecondaryColor3ubEXT(GLubyte red, GLubyte green, GLubyte blue) {
  glSecondaryColor3ub(red, green, blue);
}
void glSecondaryColor3ubvEXT(const GLubyte* v) { glSecondaryColor3ubv(v); }
void glSecondaryColor3uiEXT(GLuint red, GLuint green, GLuint blue) {
  glSecondaryColor3ui(red, green, blue);
}
void glSecondaryColor3uivEXT(const GLuint* v) { glSecondaryColor3uiv(v); }
void glSecondaryColor3usEXT(GLushort red, GLushort green, GLushort blue) {
  glSecondaryColor3us(red, green, blue);
}
void glSecondaryColor3usvEXT(const GLushort* v) { glSecondaryColor3usv(v); }
void glSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride, const void* pointer) {
  glSecondaryColorPointer(size, type, stride, pointer);
}

// GL_EXT_subtexture
void glTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                        GLenum type, const void* pixels) {
  glTexSubImage1D(target, level, xoffset, width, format, type, pixels);
}
void glTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                        GLsizei height, GLenum format, GLenum type, const void* pixels) {
  glTexSubImage2D(target, level, xoffset, yoffset, width, height, format, type, pixels);
}

// GL_EXT_texture3D
void glTexImage3DEXT(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                     GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                     const void* pixels) {
  glTexImage3D(target, level, static_cast<GLint>(internalformat), width, height, depth, border,
               format, type, pixels);
}
void glTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                        GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                        const void* pixels) {
  glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format, type,
                  pixels);
}

// GL_EXT_texture_object
GLboolean glAreTexturesResidentEXT(GLsizei n, const GLuint* textures, GLboolean* residences) {
  return glAreTexturesResident(n, textures, residences);
}
void glBindTextureEXT(GLenum target, GLuint texture) { glBindTexture(target, texture); }
void glDeleteTexturesEXT(GLsizei n, const GLuint* textures) { glDeleteTextures(n, textures); }
void glGenTexturesEXT(GLsizei n, GLuint* textures) { glGenTextures(n, textures); }
GLboolean glIsTextureEXT(GLuint texture) { return glIsTexture(texture); }
void glPrioritizeTexturesEXT(GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  glPrioritizeTextures(n, textures, priorities);
}

}  // extern "C"
