// The imaging subset's colour tables, convolution, histogram and minmax (OpenGL 1.2, spec
// 3.6.3 and 4.3.3; GL_ARB_imaging). glass does not implement them and does not advertise
// GL_ARB_imaging; glBlendColor and glBlendEquation, which GL 1.4 made core, are implemented
// (fragment/blending.h). The entry points exist so that programs written for either link, and
// each sets GL_INVALID_OPERATION and does nothing, as Mesa does in every context (it removed the
// subset and keeps these entry points the same way). GL_COLOR_TABLE, GL_CONVOLUTION_1D/2D,
// GL_SEPARABLE_2D, GL_HISTOGRAM and GL_MINMAX are not capabilities: glEnable sets
// GL_INVALID_ENUM for them, as for any unknown capability.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::Context;

namespace {

// Outside a display list, or when a list containing it executes, the command fails.
void unsupportedCommand() {
  glass::gl::compileOrExecute(
      [](Context& ctx) { glass::gl::recordError(ctx, GL_INVALID_OPERATION); });
}

// Queries are never compiled (spec 5.4).
void unsupportedQuery() {
  glass::gl::executeNow([](Context& ctx) { glass::gl::recordError(ctx, GL_INVALID_OPERATION); });
}

}  // namespace

extern "C" {

void glColorTable(GLenum, GLenum, GLsizei, GLenum, GLenum, const GLvoid*) { unsupportedCommand(); }
void glColorSubTable(GLenum, GLsizei, GLsizei, GLenum, GLenum, const GLvoid*) {
  unsupportedCommand();
}
void glColorTableParameteriv(GLenum, GLenum, const GLint*) { unsupportedCommand(); }
void glColorTableParameterfv(GLenum, GLenum, const GLfloat*) { unsupportedCommand(); }
void glCopyColorSubTable(GLenum, GLsizei, GLint, GLint, GLsizei) { unsupportedCommand(); }
void glCopyColorTable(GLenum, GLenum, GLint, GLint, GLsizei) { unsupportedCommand(); }
void glGetColorTable(GLenum, GLenum, GLenum, GLvoid*) { unsupportedQuery(); }
void glGetColorTableParameterfv(GLenum, GLenum, GLfloat*) { unsupportedQuery(); }
void glGetColorTableParameteriv(GLenum, GLenum, GLint*) { unsupportedQuery(); }

void glHistogram(GLenum, GLsizei, GLenum, GLboolean) { unsupportedCommand(); }
void glResetHistogram(GLenum) { unsupportedCommand(); }
void glGetHistogram(GLenum, GLboolean, GLenum, GLenum, GLvoid*) { unsupportedQuery(); }
void glGetHistogramParameterfv(GLenum, GLenum, GLfloat*) { unsupportedQuery(); }
void glGetHistogramParameteriv(GLenum, GLenum, GLint*) { unsupportedQuery(); }
void glMinmax(GLenum, GLenum, GLboolean) { unsupportedCommand(); }
void glResetMinmax(GLenum) { unsupportedCommand(); }
void glGetMinmax(GLenum, GLboolean, GLenum, GLenum, GLvoid*) { unsupportedQuery(); }
void glGetMinmaxParameterfv(GLenum, GLenum, GLfloat*) { unsupportedQuery(); }
void glGetMinmaxParameteriv(GLenum, GLenum, GLint*) { unsupportedQuery(); }

void glConvolutionFilter1D(GLenum, GLenum, GLsizei, GLenum, GLenum, const GLvoid*) {
  unsupportedCommand();
}
void glConvolutionFilter2D(GLenum, GLenum, GLsizei, GLsizei, GLenum, GLenum, const GLvoid*) {
  unsupportedCommand();
}
void glConvolutionParameterf(GLenum, GLenum, GLfloat) { unsupportedCommand(); }
void glConvolutionParameterfv(GLenum, GLenum, const GLfloat*) { unsupportedCommand(); }
void glConvolutionParameteri(GLenum, GLenum, GLint) { unsupportedCommand(); }
void glConvolutionParameteriv(GLenum, GLenum, const GLint*) { unsupportedCommand(); }
void glCopyConvolutionFilter1D(GLenum, GLenum, GLint, GLint, GLsizei) { unsupportedCommand(); }
void glCopyConvolutionFilter2D(GLenum, GLenum, GLint, GLint, GLsizei, GLsizei) {
  unsupportedCommand();
}
void glGetConvolutionFilter(GLenum, GLenum, GLenum, GLvoid*) { unsupportedQuery(); }
void glGetConvolutionParameterfv(GLenum, GLenum, GLfloat*) { unsupportedQuery(); }
void glGetConvolutionParameteriv(GLenum, GLenum, GLint*) { unsupportedQuery(); }
void glSeparableFilter2D(GLenum, GLenum, GLsizei, GLsizei, GLenum, GLenum, const GLvoid*,
                         const GLvoid*) {
  unsupportedCommand();
}
void glGetSeparableFilter(GLenum, GLenum, GLenum, GLvoid*, GLvoid*, GLvoid*) {
  unsupportedQuery();
}

}  // extern "C"
