/* Antialiased lines drawn twice with a GL_LESS depth test, as wireframes are often drawn (every
 * edge once from each of its faces, so in both directions): a wire cube and a wire circle, each
 * edge drawn from a to b and then from b to a at the same depth, blended with GL_SRC_ALPHA,
 * GL_ONE_MINUS_SRC_ALPHA. The specification gives a line's fragments the depth
 * z = (1 - t) z_a + t z_b of their position t along the segment (section 3.4.1), which is the
 * same for both directions, so the second drawing fails GL_LESS wherever the first one wrote
 * depth, and each pixel is blended once. In the right half the same edges are drawn once, for
 * comparison: the two halves must look the same. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 160 };

static void edge(const float *a, const float *b, int twice)
{
  glBegin(GL_LINES);
  glVertex3fv(a);
  glVertex3fv(b);
  if (twice) {
    glVertex3fv(b);
    glVertex3fv(a);
  }
  glEnd();
}

static void wireframes(int twice)
{
  static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  float circle[33][3];
  int i;
  glPushMatrix();
  glTranslatef(-0.9f, 0.0f, 0.0f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
  glScalef(0.55f, 0.55f, 0.55f);
  glColor3f(0.1f, 0.2f, 0.5f);
  for (i = 0; i < 12; ++i) edge(corners[edges[i][0]], corners[edges[i][1]], twice);
  glPopMatrix();
  for (i = 0; i <= 32; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / 32;
    circle[i][0] = 0.9f + 0.8f * (float)cos(angle);
    circle[i][1] = 0.8f * (float)sin(angle);
    circle[i][2] = 0.3f * (float)cos(3.0 * angle);
  }
  glColor3f(0.5f, 0.1f, 0.1f);
  for (i = 0; i < 32; ++i) edge(circle[i], circle[i + 1], twice);
}

static void draw(void)
{
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glLineWidth(1.5f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glViewport(0, 0, WIDTH / 2, HEIGHT);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  wireframes(1);
  glViewport(WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  wireframes(0);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
