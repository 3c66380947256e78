/* A torus made of sixteen rational biquadratic Bezier patches, each given to glMap2 as
 * GL_MAP2_VERTEX_4 (homogeneous control points w (x, y, z), w) and drawn by glEvalMesh2 with
 * GL_AUTO_NORMAL and lighting (section 5.1 of the GL 1.5 specification).
 *
 * The torus is the exam's (study guide, section 4.1): x = (R + r cos t) sin f, y = r sin t,
 * z = (R + r cos t) cos f. A quarter of a circle is the rational quadratic with control points
 * (1, 0), (1, 1), (0, 1) and weights 1, sqrt(2)/2, 1; the patch is the tensor product of a quarter
 * of the tube circle and a quarter turn about the y axis, its weights the products of the two
 * curves' weights. The automatic normal differentiates the point after the division by w (the
 * quotient rule), so the shading is that of the exact torus. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { SIZE = 320, GRID = 8 };

/* The unit circle's eight quarter-arc control points, counter-clockwise from (1, 0), with their
 * weights: quarter q has the points 2q, 2q + 1, 2q + 2. */
static const float circle[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};

static float circleWeight(int k) { return k % 2 ? (float)(sqrt(2.0) / 2.0) : 1.0f; }

/* Patch (ring quarter a, tube quarter b): 3 x 3 homogeneous points, u along the ring. */
static void torusPatch(float R, float r, int a, int b, GLfloat points[3][3][4])
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const float *ring = circle[2 * a + i];
      const float *tube = circle[2 * b + j];
      const float w = circleWeight(2 * a + i) * circleWeight(2 * b + j);
      const float rho = R + r * tube[0];
      /* (sin f, cos f) runs along ring = (cos, sin) of the quarter turn: x from ring[1], z from
       * ring[0]; the same rotation sense as the exam's parametrisation. */
      points[i][j][0] = w * rho * ring[1];
      points[i][j][1] = w * r * tube[1];
      points[i][j][2] = w * rho * ring[0];
      points[i][j][3] = w;
    }
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {-1.0f, 2.0f, 3.0f, 0.0f};
  static const GLfloat copper[4] = {0.8f, 0.45f, 0.25f, 1.0f};
  static const GLfloat specular[4] = {0.7f, 0.7f, 0.7f, 1.0f};

  glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(35.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, copper);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  gluLookAt(0.0, 5.0, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glRotatef(20.0f, 0.0f, 0.0f, 1.0f);

  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(GRID, 0.0f, 1.0f, GRID, 0.0f, 1.0f);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      GLfloat points[3][3][4];
      torusPatch(2.0f, 0.8f, a, b, points);
      glMap2f(GL_MAP2_VERTEX_4, 0.0f, 1.0f, 12, 3, 0.0f, 1.0f, 4, 3, &points[0][0][0]);
      glEvalMesh2(GL_FILL, 0, GRID, 0, GRID);
    }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, SIZE, SIZE, draw);
}
