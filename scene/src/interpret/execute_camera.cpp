// Output, camera and transform statements.
#include "interpret/executor.h"

#include "glass/scene/render.h"

#include <glass/geometry/quaternion.h>

#include <algorithm>
#include <cmath>

namespace glass::scene {

namespace {

// The camera statements replace the projection matrix, as a GL program's reshape function does
// (glMatrixMode(GL_PROJECTION); glLoadIdentity(); ...; glMatrixMode(GL_MODELVIEW)).
template <typename F> void setProjection(F &&multiply) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  multiply();
  glMatrixMode(GL_MODELVIEW);
}

double viewportAspect() {
  GLint viewport[4] = {0, 0, 1, 1};
  glGetIntegerv(GL_VIEWPORT, viewport);
  return viewport[3] > 0 ? static_cast<double>(viewport[2]) / viewport[3] : 1.0;
}

// The viewer's projection (glass view) in place of the scene's.
void setViewerProjection(const ViewCamera &camera) {
  const double aspect = viewportAspect();
  setProjection([&] {
    if (camera.orthographic) {
      glOrtho(-camera.halfHeight * aspect, camera.halfHeight * aspect, -camera.halfHeight,
              camera.halfHeight, camera.zNear, camera.zFar);
    } else {
      gluPerspective(camera.fovy, aspect, camera.zNear, camera.zFar);
    }
  });
}

} // namespace

void Interpreter::Executor::run(const Viewport &s) {
  std::vector<double> v = values(s.rect);
  if (v[2] < 0 || v[3] < 0) fail("the viewport's width and height must not be negative");
  glViewport(scaledX(v[0]), scaledY(v[1]), scaledX(v[2]), scaledY(v[3]));
}

void Interpreter::Executor::run(const ClearColor &s) {
  std::vector<double> c = values(s.rgba);
  glClearColor(static_cast<GLclampf>(c[0]), static_cast<GLclampf>(c[1]), static_cast<GLclampf>(c[2]),
               static_cast<GLclampf>(c[3]));
}

void Interpreter::Executor::run(const ClearDepth &s) { glClearDepth(value(s.depth)); }

void Interpreter::Executor::run(const ClearStencil &s) {
  if (!options_.countOverdraw) glClearStencil(s.value);
}

void Interpreter::Executor::run(const Clear &s) {
  GLbitfield mask = s.mask;
  // The overdraw count lives in the stencil buffer and covers the whole frame.
  if (options_.countOverdraw) mask &= ~static_cast<GLbitfield>(GL_STENCIL_BUFFER_BIT);
  if (mask != 0) glClear(mask);
}

void Interpreter::Executor::run(const Perspective &s) {
  // `auto`: the aspect ratio of the current viewport, as a reshape function computes it.
  const double aspect = s.aspect ? value(*s.aspect) : viewportAspect();
  double fovy = value(s.fovy), zNear = value(s.zNear), zFar = value(s.zFar);
  if (!(fovy > 0.0 && fovy < 180.0)) fail("the field of view must be between 0 and 180 degrees");
  if (!(zNear > 0.0 && zFar > zNear)) fail("perspective needs 0 < near < far");
  if (SceneCamera *seen = options_.sceneCamera; seen && !seen->hasPerspective) {
    seen->hasPerspective = true;
    seen->fovy = fovy;
    seen->zNear = zNear;
    seen->zFar = zFar;
  }
  if (options_.camera) return setViewerProjection(*options_.camera);
  setProjection([&] { gluPerspective(fovy, aspect, zNear, zFar); });
}

void Interpreter::Executor::run(const Frustum &s) {
  std::vector<double> p = values(s.planes);
  if (options_.camera) return setViewerProjection(*options_.camera);
  setProjection([&] { glFrustum(p[0], p[1], p[2], p[3], p[4], p[5]); });
}

void Interpreter::Executor::run(const Ortho &s) {
  std::vector<double> p = values(s.planes);
  if (options_.camera) return setViewerProjection(*options_.camera);
  if (p.size() == 4) {
    setProjection([&] { gluOrtho2D(p[0], p[1], p[2], p[3]); });
  } else {
    setProjection([&] { glOrtho(p[0], p[1], p[2], p[3], p[4], p[5]); });
  }
}

void Interpreter::Executor::run(const LookAt &s) {
  std::vector<double> v = values(s.values);
  if (SceneCamera *seen = options_.sceneCamera; seen && !seen->hasLookAt) {
    seen->hasLookAt = true;
    std::copy(v.begin(), v.begin() + 9, seen->lookAt);
  }
  if (const ViewCamera *c = options_.camera) {
    gluLookAt(c->eye[0], c->eye[1], c->eye[2], c->centre[0], c->centre[1], c->centre[2], c->up[0],
              c->up[1], c->up[2]);
    return;
  }
  gluLookAt(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
}

void Interpreter::Executor::run(const LoadIdentity &) { glLoadIdentity(); }

void Interpreter::Executor::run(const Translate &s) {
  std::vector<double> v = values(s.v);
  glTranslated(v[0], v[1], v[2]);
}

void Interpreter::Executor::run(const Rotate &s) {
  std::vector<double> axis = values(s.axis);
  glRotated(value(s.angle), axis[0], axis[1], axis[2]);
}

void Interpreter::Executor::run(const RotateQuaternion &s) {
  std::vector<double> q = values(s.wxyz);
  geometry::Quaternion quaternion(q[0], q[1], q[2], q[3]);
  if (geometry::normSquared(quaternion) == 0.0) fail("the quaternion 0 0 0 0 is no rotation");
  // The guide's equation 8, for the normalised quaternion, as a 4x4 matrix (column-major for GL).
  glm::dmat3 r = geometry::rotationMatrix(quaternion);
  GLdouble m[16] = {r[0][0], r[0][1], r[0][2], 0, r[1][0], r[1][1], r[1][2], 0,
                    r[2][0], r[2][1], r[2][2], 0, 0,       0,       0,       1};
  glMultMatrixd(m);
}

void Interpreter::Executor::run(const RotateByParameter &s) {
  const std::vector<double> &r = values_.values[static_cast<std::size_t>(s.parameter)];
  if (r[1] == 0.0 && r[2] == 0.0 && r[3] == 0.0) {
    if (r[0] != 0.0) fail("the rotation axis 0 0 0 has no direction");
    return;
  }
  glRotated(r[0], r[1], r[2], r[3]);
}

void Interpreter::Executor::run(const Scale &s) {
  std::vector<double> v = values(s.v);
  glScaled(v[0], v[1], v[2]);
}

void Interpreter::Executor::run(const MultMatrix &s) {
  std::vector<double> v = values(s.rowMajor);
  GLdouble m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (v.size() == 16) {
    // Written row by row, as on paper; GL takes columns.
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) m[c * 4 + r] = v[static_cast<std::size_t>(r * 4 + c)];
    }
  } else {
    // The 2D affine map [a11 a12 a13; a21 a22 a23; 0 0 1] acting on x and y, z unchanged.
    m[0] = v[0], m[4] = v[1], m[12] = v[2];
    m[1] = v[3], m[5] = v[4], m[13] = v[5];
  }
  glMultMatrixd(m);
}

// The planar projection shadow (as in the OpenGL Programming Guide's shadow technique): with the
// plane P = (a, b, c, d) and the light L = (x, y, z, w), the matrix M = (P.L) I - L P^T sends
// every point p to where the ray from L through p meets the plane (a light with w = 0 casts
// parallel rays along -(x, y, z)).
void Interpreter::Executor::run(const ShadowMatrix &s) {
  std::vector<double> p = values(s.plane), l = values(s.light);
  const double dot = p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3] * l[3];
  if (dot == 0.0) fail("the light lies in the shadow's plane: no shadow can be cast");
  GLdouble m[16];
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      m[column * 4 + row] = (row == column ? dot : 0.0) - l[static_cast<std::size_t>(row)] * p[static_cast<std::size_t>(column)];
    }
  }
  glMultMatrixd(m);
}

void Interpreter::Executor::run(const Push &) {
  glPushMatrix();
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  saveCurrentValues();
}

void Interpreter::Executor::run(const Pop &) {
  glPopAttrib();
  glPopMatrix();
  resendCurrentValues();
}

// glPopAttrib restores the current colour, normal, texture coordinates and edge flag (OpenGL 1.4,
// table 6.5, GL_CURRENT_BIT), so sending the restored values again is a no-op by the
// specification. Mesa 22 keeps a second copy of the current values for immediate mode that
// glPopAttrib does not update: the vertices after the pop are drawn with the values from before
// it, and glGet may even copy those back. So the values are read before glPushAttrib, when both
// copies agree, and sent again after glPopAttrib.
// With GL_COLOR_MATERIAL enabled Mesa also gives the tracked material the colour from before the
// pop; enabling GL_COLOR_MATERIAL again sets the tracked material to the current colour (section
// 2.13.3), which the restored material already is.
// While a definition is being compiled glGet would read the values of compile time, not those of
// the instance, so nothing is saved or sent there (and Mesa's display lists restore them right).
void Interpreter::Executor::saveCurrentValues() {
  if (compilingDefinition_ > 0) return;
  CurrentValues saved;
  GLboolean edgeFlag = GL_TRUE;
  glGetDoublev(GL_CURRENT_COLOR, saved.color);
  glGetDoublev(GL_CURRENT_NORMAL, saved.normal);
  glGetDoublev(GL_CURRENT_TEXTURE_COORDS, saved.texcoord);
  glGetBooleanv(GL_EDGE_FLAG, &edgeFlag);
  saved.edgeFlag = edgeFlag;
  savedCurrentValues_.push_back(saved);
}

void Interpreter::Executor::resendCurrentValues() {
  if (compilingDefinition_ > 0 || savedCurrentValues_.empty()) return;
  const CurrentValues saved = savedCurrentValues_.back();
  savedCurrentValues_.pop_back();
  glColor4dv(saved.color);
  glNormal3dv(saved.normal);
  glTexCoord4dv(saved.texcoord);
  glEdgeFlag(saved.edgeFlag);
  if (glIsEnabled(GL_COLOR_MATERIAL)) {
    glDisable(GL_COLOR_MATERIAL);
    glEnable(GL_COLOR_MATERIAL);
  }
}

} // namespace glass::scene
