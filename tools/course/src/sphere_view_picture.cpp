#include "glass/course/sphere_view_picture.h"

#include <glass/context.h>

#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>

namespace glass::course {

SphereViewMeasurement renderSphereView(const geometry::SphereViewSolution& s, double radius, int heightPixels,
                                       const char* path) {
  SphereViewMeasurement m;
  m.height = heightPixels;
  m.width = std::max(1, static_cast<int>(std::lround(heightPixels * s.aspect)));
  GlassContext* previous = glassGetCurrentContext();
  GlassContext* context = glassCreateContext(m.width, m.height);
  if (context == nullptr || !glassMakeCurrent(context)) {
    glassDestroyContext(context);
    return m;
  }
  glViewport(0, 0, m.width, m.height);
  glClearColor(0.08f, 0.09f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  // The answer, in the exam's order.
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(s.eye.x, s.eye.y, s.eye.z, s.center.x, s.center.y, s.center.z, s.up.x, s.up.y, s.up.z);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(s.fovyDegrees, s.aspect, s.zNear, s.zFar);

  // A light at the eye; two-sided, so the inside of the far half (seen through the cut) is lit.
  glMatrixMode(GL_MODELVIEW);
  const GLfloat light[4] = {static_cast<GLfloat>(s.eye.x), static_cast<GLfloat>(s.eye.y),
                            static_cast<GLfloat>(s.eye.z), 1.0f};
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const GLfloat ambient[4] = {0.15f, 0.15f, 0.15f, 1.0f};
  const GLfloat outside[4] = {0.85f, 0.45f, 0.20f, 1.0f};
  const GLfloat inside[4] = {0.30f, 0.60f, 0.90f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, outside);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, inside);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_CULL_FACE);

  glPushMatrix();
  glTranslated(s.center.x, s.center.y, s.center.z);
  GLUquadric* sphere = gluNewQuadric();
  gluQuadricNormals(sphere, GLU_SMOOTH);
  // The surface, pushed back a little so that the grid of meridians and parallels drawn next
  // lies on it: the grid shows the inside of a bowl, where plain shading would look like a ball.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  gluSphere(sphere, radius, 96, 64);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_LIGHTING);
  glDepthFunc(GL_LEQUAL);
  glColor3f(0.10f, 0.25f, 0.45f);
  gluQuadricDrawStyle(sphere, GLU_LINE);
  gluSphere(sphere, radius, 24, 16);
  gluDeleteQuadric(sphere);
  glPopMatrix();

  // Measure: rows and columns with any pixel brighter than the background.
  const unsigned char* pixels = glassGetColorBuffer(context);
  int top = -1, bottom = m.height, left = m.width, right = -1;
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const unsigned char* p = pixels + (static_cast<std::size_t>(y) * m.width + x) * 4;
      if (std::abs(p[0] - 20) + std::abs(p[1] - 23) + std::abs(p[2] - 31) > 12) {
        top = std::max(top, y);
        bottom = std::min(bottom, y);
        left = std::min(left, x);
        right = std::max(right, x);
      }
    }
  }
  if (top >= bottom) {
    m.rows = top - bottom + 1;
    m.columns = right - left + 1;
  }
  m.drawn = path == nullptr || glassWritePNG(context, path) != 0;
  glassDestroyContext(context);
  glassMakeCurrent(previous);
  return m;
}

}  // namespace glass::course
