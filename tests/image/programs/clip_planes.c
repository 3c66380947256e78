/* User clip planes (glClipPlane, section 2.11 of the GL 1.5 specification) on a smooth shaded
 * torus, on lines and on points.
 *
 * Three planes, each given under a different modelview matrix, since glClipPlane transforms the
 * plane by the inverse of the modelview matrix current when it is called:
 *   plane 0, under the identity: keeps x <= 0.45 + 0.3 y (a slanted cut on the right);
 *   plane 1, under a 30 degree turn about z: keeps y' >= -0.55 in the turned frame (a tilted
 *            cut at the bottom);
 *   plane 2, under the torus's own tilt: keeps the torus's z <= 0.15 in its frame, a cut through
 *            the tube that opens it up so the inside shows.
 * The torus is drawn as triangle strips (no quads, so the split of faces is not in question). A
 * ring of lines and a ring of points around it are clipped by planes 0 and 1. */
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { SIZE = 320 };

static const float PI = 3.14159265358979f;

static void torus(void)
{
  const int rings = 32, sides = 16;
  const float major = 0.75f, minor = 0.3f;
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= sides; ++j)
      for (int k = 1; k >= 0; --k) {
        const float u = 2.0f * PI * (float)(i + k) / (float)rings;
        const float v = 2.0f * PI * (float)j / (float)sides;
        const float r = major + minor * cosf(v);
        /* Colour around the ring, darker on the inside of the tube. */
        const float shade = 0.55f + 0.45f * cosf(v);
        glColor3f(shade * (0.5f + 0.5f * cosf(u)), shade * (0.5f + 0.5f * cosf(u - 2.0944f)),
                  shade * (0.5f + 0.5f * cosf(u + 2.0944f)));
        glVertex3f(r * cosf(u), r * sinf(u), minor * sinf(v));
      }
    glEnd();
  }
}

static void linesAndPoints(void)
{
  glBegin(GL_LINES);
  for (int i = 0; i < 48; ++i) {
    const float angle = 2.0f * PI * (float)i / 48.0f;
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(1.15f * cosf(angle), 1.15f * sinf(angle), 0.0f);
    glColor3f(0.3f, 0.3f, 0.4f);
    glVertex3f(1.4f * cosf(angle), 1.4f * sinf(angle), 0.0f);
  }
  glEnd();
  glPointSize(3.0f);
  glBegin(GL_POINTS);
  glColor3f(1.0f, 0.9f, 0.3f);
  for (int i = 0; i < 48; ++i) {
    const float angle = 2.0f * PI * ((float)i + 0.5f) / 48.0f;
    glVertex3f(1.05f * cosf(angle), 1.05f * sinf(angle), 0.0f);
  }
  glEnd();
  glPointSize(1.0f);
}

static void draw(void)
{
  static const GLdouble slantedRight[4] = {-1.0, 0.3, 0.0, 0.45};
  static const GLdouble tiltedBottom[4] = {0.0, 1.0, 0.0, 0.55};
  static const GLdouble throughTube[4] = {0.0, 0.0, -1.0, 0.15};

  glViewport(0, 0, SIZE, SIZE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.5, 1.5, -3.0, 3.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glClipPlane(GL_CLIP_PLANE0, slantedRight);
  glPushMatrix();
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glClipPlane(GL_CLIP_PLANE1, tiltedBottom);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE1);

  linesAndPoints();

  glPushMatrix();
  glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
  glClipPlane(GL_CLIP_PLANE2, throughTube);
  glEnable(GL_CLIP_PLANE2);
  torus();
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, SIZE, SIZE, draw); }
