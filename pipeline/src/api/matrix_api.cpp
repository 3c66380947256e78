// Matrices, viewport, depth range and user clip planes (spec 2.11, 2.12).
#include <GL/gl.h>

#include <algorithm>
#include <array>

#include "core/context.h"
#include "core/matrix_transforms.h"
#include "lists/command_recording.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::Matrix4;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;

namespace {

// The stack glMatrixMode selects; GL_TEXTURE's is the active texture unit's (spec 2.11.2), and
// GL_COLOR's the imaging subset's colour matrix stack (spec 3.6.3, pixels/imaging_state.h).
glass::gl::MatrixStack& currentMatrixStack(Context& ctx) {
  if (ctx.transform.matrixMode == GL_COLOR) return ctx.imaging.colorMatrix;
  return ctx.transform.currentStack(ctx.texture.activeUnit);
}

// Every matrix command is compiled into display lists and is not allowed inside glBegin/glEnd.
template <class Update>
void matrixCommand(Update update) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    update(ctx, currentMatrixStack(ctx).top());
  });
}

void multiplyCurrent(const Matrix4& m) {
  matrixCommand([=](Context&, Matrix4& top) { top = glass::gl::multiply(top, m); });
}

template <class T>
Matrix4 toMatrix(const T* m) {
  Matrix4 result;
  for (int i = 0; i < 16; ++i) result.m[i] = static_cast<float>(m[i]);
  return result;
}

void rotate(float angle, float x, float y, float z) {
  Matrix4 r;
  if (!glass::gl::rotationMatrix(angle, x, y, z, r)) {
    matrixCommand([](Context&, Matrix4&) {});  // still an error inside glBegin/glEnd
    return;
  }
  multiplyCurrent(r);
}

void ortho(double l, double r, double b, double t, double n, double f) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (l == r || b == t || n == f) return recordError(ctx, GL_INVALID_VALUE);
    Matrix4& top = currentMatrixStack(ctx).top();
    top = glass::gl::multiply(top, glass::gl::orthoMatrix(l, r, b, t, n, f));
  });
}

void frustum(double l, double r, double b, double t, double n, double f) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (n <= 0.0 || f <= 0.0 || l == r || b == t || n == f) {
      return recordError(ctx, GL_INVALID_VALUE);
    }
    Matrix4& top = currentMatrixStack(ctx).top();
    top = glass::gl::multiply(top, glass::gl::frustumMatrix(l, r, b, t, n, f));
  });
}

}  // namespace

extern "C" {

void glMatrixMode(GLenum mode) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE && mode != GL_COLOR) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    ctx.transform.matrixMode = mode;
  });
}

void glLoadIdentity(void) {
  matrixCommand([](Context&, Matrix4& top) { top = Matrix4::identity(); });
}

void glLoadMatrixf(const GLfloat* m) {
  if (!m) return;
  const Matrix4 matrix = toMatrix(m);
  matrixCommand([=](Context&, Matrix4& top) { top = matrix; });
}

void glLoadMatrixd(const GLdouble* m) {
  if (!m) return;
  const Matrix4 matrix = toMatrix(m);
  matrixCommand([=](Context&, Matrix4& top) { top = matrix; });
}

void glMultMatrixf(const GLfloat* m) {
  if (m) multiplyCurrent(toMatrix(m));
}

void glMultMatrixd(const GLdouble* m) {
  if (m) multiplyCurrent(toMatrix(m));
}

void glPushMatrix(void) {
  compileOrExecute([](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (!currentMatrixStack(ctx).push()) recordError(ctx, GL_STACK_OVERFLOW);
  });
}

void glPopMatrix(void) {
  compileOrExecute([](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (!currentMatrixStack(ctx).pop()) recordError(ctx, GL_STACK_UNDERFLOW);
  });
}

void glTranslatef(GLfloat x, GLfloat y, GLfloat z) {
  multiplyCurrent(glass::gl::translationMatrix(x, y, z));
}
void glTranslated(GLdouble x, GLdouble y, GLdouble z) {
  multiplyCurrent(glass::gl::translationMatrix(static_cast<float>(x), static_cast<float>(y),
                                               static_cast<float>(z)));
}
void glScalef(GLfloat x, GLfloat y, GLfloat z) { multiplyCurrent(glass::gl::scaleMatrix(x, y, z)); }
void glScaled(GLdouble x, GLdouble y, GLdouble z) {
  multiplyCurrent(glass::gl::scaleMatrix(static_cast<float>(x), static_cast<float>(y),
                                         static_cast<float>(z)));
}
void glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { rotate(angle, x, y, z); }
void glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  rotate(static_cast<float>(angle), static_cast<float>(x), static_cast<float>(y),
         static_cast<float>(z));
}

void glOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  ortho(l, r, b, t, n, f);
}
void glFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  frustum(l, r, b, t, n, f);
}

void glViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (width < 0 || height < 0) return recordError(ctx, GL_INVALID_VALUE);
    // Spec 2.11.1: width and height are clamped to GL_MAX_VIEWPORT_DIMS.
    ctx.transform.viewport = glass::gl::Viewport{x, y, std::min(width, glass::gl::kMaxViewportSize),
                                                 std::min(height, glass::gl::kMaxViewportSize)};
  });
}

void glDepthRange(GLclampd zNear, GLclampd zFar) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    ctx.transform.depthNear = std::clamp(zNear, 0.0, 1.0);
    ctx.transform.depthFar = std::clamp(zFar, 0.0, 1.0);
  });
}

void glClipPlane(GLenum plane, const GLdouble* equation) {
  if (!equation) return;
  const std::array<double, 4> p = {equation[0], equation[1], equation[2], equation[3]};
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + glass::raster::kMaxUserClipPlanes) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    // Spec 2.12: the plane is transformed to eye space by the inverse of the modelview matrix
    // current now: (p1' p2' p3' p4') = (p1 p2 p3 p4) M^-1.
    Matrix4 inverse;
    glass::gl::invert(ctx.transform.modelview.top(), inverse);
    double* eye = ctx.transform.clipPlanes[plane - GL_CLIP_PLANE0];
    for (int j = 0; j < 4; ++j) {
      eye[j] = p[0] * inverse.at(0, j) + p[1] * inverse.at(1, j) + p[2] * inverse.at(2, j) +
               p[3] * inverse.at(3, j);
    }
  });
}

void glGetClipPlane(GLenum plane, GLdouble* equation) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + glass::raster::kMaxUserClipPlanes) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    if (!equation) return;
    const double* eye = ctx.transform.clipPlanes[plane - GL_CLIP_PLANE0];
    for (int j = 0; j < 4; ++j) equation[j] = eye[j];
  });
}

}  // extern "C"
