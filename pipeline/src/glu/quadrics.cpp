// The GLU quadric objects and their drawing commands (GLU 1.3 specification, chapter 6). The
// shapes themselves are generated in quadric_sphere.cpp, quadric_cylinder.cpp and
// quadric_disk.cpp; here they are sent to the GL as immediate-mode calls, as GLU does, so they
// also compile into display lists.
#include <GL/gl.h>
#include <GL/glu.h>

#include <new>

#include "glu/quadric_emitter.h"

using glass::gl::glu::QuadricStyle;

struct GLUquadric {
  QuadricStyle style;
  void (*errorCallback)(GLenum) = nullptr;  // gluQuadricCallback(GLU_ERROR)
};

namespace {

namespace quadric = glass::gl::glu;

class GLEmitter final : public quadric::PrimitiveEmitter {
 public:
  void begin(GLenum mode) override { glBegin(mode); }
  void normal(float x, float y, float z) override { glNormal3f(x, y, z); }
  void texCoord(float s, float t) override { glTexCoord2f(s, t); }
  void vertex(float x, float y, float z) override { glVertex3f(x, y, z); }
  void end() override { glEnd(); }
};

void reportError(GLUquadric* q, GLenum error) {
  if (q && q->errorCallback) q->errorCallback(error);
}

}  // namespace

extern "C" {

GLUquadric* gluNewQuadric(void) { return new (std::nothrow) GLUquadric; }

void gluDeleteQuadric(GLUquadric* q) { delete q; }

void gluQuadricCallback(GLUquadric* q, GLenum which, _GLUfuncptr callback) {
  if (!q) return;
  if (which != GLU_ERROR) {
    reportError(q, GLU_INVALID_ENUM);
    return;
  }
  q->errorCallback = reinterpret_cast<void (*)(GLenum)>(callback);
}

void gluQuadricNormals(GLUquadric* q, GLenum normals) {
  if (!q) return;
  if (normals != GLU_SMOOTH && normals != GLU_FLAT && normals != GLU_NONE) {
    reportError(q, GLU_INVALID_ENUM);
    return;
  }
  q->style.normals = normals;
}

void gluQuadricTexture(GLUquadric* q, GLboolean textureCoords) {
  if (q) q->style.textureCoords = textureCoords != GL_FALSE;
}

void gluQuadricOrientation(GLUquadric* q, GLenum orientation) {
  if (!q) return;
  if (orientation != GLU_OUTSIDE && orientation != GLU_INSIDE) {
    reportError(q, GLU_INVALID_ENUM);
    return;
  }
  q->style.orientation = orientation;
}

void gluQuadricDrawStyle(GLUquadric* q, GLenum drawStyle) {
  if (!q) return;
  if (drawStyle != GLU_POINT && drawStyle != GLU_LINE && drawStyle != GLU_FILL &&
      drawStyle != GLU_SILHOUETTE) {
    reportError(q, GLU_INVALID_ENUM);
    return;
  }
  q->style.drawStyle = drawStyle;
}

void gluSphere(GLUquadric* q, GLdouble radius, GLint slices, GLint stacks) {
  if (!q) return;
  GLEmitter gl;
  if (!quadric::emitSphere(q->style, radius, slices, stacks, gl)) {
    reportError(q, GLU_INVALID_VALUE);
  }
}

void gluCylinder(GLUquadric* q, GLdouble baseRadius, GLdouble topRadius, GLdouble height,
                 GLint slices, GLint stacks) {
  if (!q) return;
  GLEmitter gl;
  if (!quadric::emitCylinder(q->style, baseRadius, topRadius, height, slices, stacks, gl)) {
    reportError(q, GLU_INVALID_VALUE);
  }
}

void gluDisk(GLUquadric* q, GLdouble innerRadius, GLdouble outerRadius, GLint slices,
             GLint loops) {
  gluPartialDisk(q, innerRadius, outerRadius, slices, loops, 0.0, 360.0);
}

void gluPartialDisk(GLUquadric* q, GLdouble innerRadius, GLdouble outerRadius, GLint slices,
                    GLint loops, GLdouble startAngle, GLdouble sweepAngle) {
  if (!q) return;
  GLEmitter gl;
  if (!quadric::emitPartialDisk(q->style, innerRadius, outerRadius, slices, loops, startAngle,
                                sweepAngle, gl)) {
    reportError(q, GLU_INVALID_VALUE);
  }
}

}  // extern "C"
