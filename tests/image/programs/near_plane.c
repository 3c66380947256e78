/* Triangles and quads that cross the near plane, reach behind the eye, and have vertices with
 * clip w = 0, under gluPerspective.
 *
 * The eye stands 1.5 above a checkered floor looking along -z, with no tilt, so eye z is world
 * z - 3 exactly and the floor's grid line at z = 3 passes through the eye plane: those vertices
 * have w = 0. The floor reaches 6 units behind the eye. Clipping against the near plane
 * (section 2.12 of the GL 1.5 specification: in homogeneous coordinates, before the divide)
 * must cut every face so that no part behind the eye shows and nothing folds over. Two smooth
 * shaded triangles also cross the near plane, one of them with a vertex at w = 0. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void floorTiles(void)
{
  glBegin(GL_QUADS);
  for (int z = -30; z < 9; ++z)
    for (int x = -8; x < 8; ++x) {
      if ((x + z) & 1)
        glColor3f(0.85f, 0.85f, 0.8f);
      else
        glColor3f(0.2f, 0.35f, 0.55f);
      glVertex3f((float)x, 0.0f, (float)z);
      glVertex3f((float)x + 1.0f, 0.0f, (float)z);
      glVertex3f((float)x + 1.0f, 0.0f, (float)z - 1.0f);
      glVertex3f((float)x, 0.0f, (float)z - 1.0f);
    }
  glEnd();
}

static void crossingTriangles(void)
{
  glBegin(GL_TRIANGLES);
  /* A tall sail on the right, from 2 units behind the eye to 12 in front of it. */
  glColor3f(1.0f, 0.2f, 0.1f);
  glVertex3f(1.0f, 0.2f, 5.0f);
  glColor3f(1.0f, 0.9f, 0.1f);
  glVertex3f(3.0f, 0.2f, -9.0f);
  glColor3f(0.9f, 0.1f, 0.8f);
  glVertex3f(1.2f, 3.5f, -2.0f);
  /* On the left, one vertex exactly in the eye plane (w = 0). */
  glColor3f(0.1f, 1.0f, 0.4f);
  glVertex3f(-1.0f, 1.5f, 3.0f);
  glColor3f(0.1f, 0.4f, 1.0f);
  glVertex3f(-3.0f, 0.5f, -6.0f);
  glColor3f(0.0f, 0.9f, 0.9f);
  glVertex3f(-0.5f, 3.0f, -5.0f);
  glEnd();
}

static void draw(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (double)WIDTH / HEIGHT, 0.5, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -1.5f, -3.0f); /* the eye at (0, 1.5, 3) */

  glEnable(GL_DEPTH_TEST);
  glClearColor(0.55f, 0.7f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  floorTiles();
  crossingTriangles();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
