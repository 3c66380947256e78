/* Point parameters (OpenGL 1.4, spec 3.3): rows of points at eye distances 4 to 59, drawn with
 * GL_POINT_DISTANCE_ATTENUATION (1, 0, 0) (no change), (0, 0.1, 0) (linear) and
 * (0.5, 0, 0.005) (quadratic), clamped by GL_POINT_SIZE_MIN 4 and GL_POINT_SIZE_MAX 9; the same
 * with GL_POINT_SMOOTH and blending; and a row with GL_POINT_FADE_THRESHOLD_SIZE 6, which fades
 * alpha only with multisampling (glass and Mesa here have none), so it must draw as the row
 * without. The view is orthographic and narrow, so the points sit close to the eye axis: there
 * the eye distance of the specification, sqrt(x^2 + y^2 + z^2), and Mesa's |z| agree to 0.1%. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void row(int index, float r, float g, float b)
{
  int i;
  glBegin(GL_POINTS);
  for (i = 0; i < 12; ++i) {
    glColor4f(r, g, b, 1.0f);
    glVertex3f(-0.18f + 0.0327f * (float)i, 0.13f - 0.037f * (float)index, -4.0f - 5.0f * (float)i);
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat none[3] = {1.0f, 0.0f, 0.0f};
  static const GLfloat linear[3] = {0.0f, 0.1f, 0.0f};
  static const GLfloat quadratic[3] = {0.5f, 0.0f, 0.005f};
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-0.2, 0.2, -0.15, 0.15, 1.0, 70.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glPointSize(10.0f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
  row(0, 0.9f, 0.9f, 0.9f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, linear);
  row(1, 1.0f, 0.5f, 0.2f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quadratic);
  row(2, 0.3f, 1.0f, 0.4f);
  glPointParameterf(GL_POINT_SIZE_MIN, 4.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 9.0f);
  row(3, 0.4f, 0.7f, 1.0f);

  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 100.0f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, linear);
  row(4, 1.0f, 0.9f, 0.3f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
  row(5, 0.9f, 0.4f, 0.9f);
  glDisable(GL_POINT_SMOOTH);
  glDisable(GL_BLEND);

  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quadratic);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 6.0f);
  row(6, 1.0f, 0.3f, 0.3f);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
  glPointSize(1.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
