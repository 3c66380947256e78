/* Feedback (GL 1.5 specification, section 5.3): a scene is rendered in GL_FEEDBACK mode with the
 * GL_3D_COLOR type, and the picture is drawn from the feedback buffer alone: each polygon token's
 * vertices (window x, y, z and colour) become a smooth triangle, each line token a line, each
 * point token a 3-pixel point, with depth testing on the fed-back z. What the picture shows is
 * what feedback returned: clipping (the sphere cut by the near plane and the window's edges),
 * back-face culling, two-sided lighting's colours, a polygon drawn in GL_LINE mode, glPassThrough
 * markers (each switches the replay's point size), and the bitmap and pixel tokens (drawn as
 * crosses at their raster positions).
 * The scene leaves out what Mesa's feedback does differently from the specification and from
 * glass: flat shading (Mesa feeds back the vertices' own colours), GL_QUADS (Mesa splits them
 * along the other diagonal) and GL_LINE_RESET_TOKEN (Mesa does not write it). */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gl_program.h"

enum { SIZE = 300, VALUES = 200000 };

static GLfloat buffer[VALUES];

static void scene(void)
{
  const GLfloat position[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  const GLfloat front[4] = {0.9f, 0.5f, 0.2f, 1.0f}, back[4] = {0.2f, 0.5f, 0.9f, 1.0f};
  GLUquadric *quadric = gluNewQuadric();

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  /* A lit sphere cut by the near plane and the left edge of the window. */
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, front);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);
  glPushMatrix();
  glTranslatef(-1.6f, 0.6f, 1.6f);
  gluSphere(quadric, 1.5, 18, 12);
  glPopMatrix();

  /* An open cylinder: culling off, so its inside shows in the back colour. */
  glPushMatrix();
  glTranslatef(1.0f, -0.6f, 0.0f);
  glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(quadric, 0.5, 0.5, 1.0, 16, 1);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Back faces culled: of the two triangles only the counter-clockwise one is fed back. */
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 1.0f, 0.2f);
  glVertex3f(0.3f, 0.6f, 0.0f);
  glColor3f(0.2f, 1.0f, 0.2f);
  glVertex3f(1.3f, 0.7f, 0.0f);
  glVertex3f(0.8f, 1.4f, 0.0f);
  glColor3f(1.0f, 0.0f, 0.0f);
  glVertex3f(1.4f, 1.3f, 0.0f);
  glVertex3f(1.9f, 1.2f, 0.0f);
  glVertex3f(1.8f, 0.4f, 0.0f);
  glEnd();
  glDisable(GL_CULL_FACE);

  /* A polygon in GL_LINE mode, and a triangle strip. */
  glPassThrough(3.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(0.8f, 0.8f, 1.0f);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 6; ++i) {
    const float a = 1.0472f * (float)i;
    glVertex3f(-0.6f + 0.5f * cosf(a), -1.2f + 0.5f * sinf(a), 0.5f);
  }
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) {
    glColor3f(0.2f + 0.1f * (float)i, 0.3f, 0.9f - 0.1f * (float)i);
    glVertex3f(-2.2f + 0.6f * (float)(i / 2), -2.2f + 0.5f * (float)(i % 2), -1.0f);
  }
  glEnd();

  /* Lines and points, one of each outside the view. */
  glPassThrough(5.0f);
  glBegin(GL_LINES);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex3f(-1.8f, 1.9f, 0.0f);
  glColor3f(1.0f, 0.2f, 0.6f);
  glVertex3f(1.8f, 1.5f, -0.5f);
  glVertex3f(5.0f, 5.0f, 0.0f);
  glVertex3f(6.0f, 5.0f, 0.0f);
  glEnd();
  glBegin(GL_POINTS);
  glColor3f(0.3f, 1.0f, 1.0f);
  glVertex3f(1.5f, -1.5f, 0.2f);
  glVertex3f(0.0f, 9.0f, 0.0f);
  glEnd();

  /* Pixel commands leave tokens at their raster positions. */
  glColor3f(1.0f, 0.6f, 0.0f);
  glRasterPos3f(0.1f, -0.5f, 0.5f);
  glBitmap(0, 0, 0.0f, 0.0f, 20.0f, -10.0f, NULL);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_BYTE, buffer);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);

  gluDeleteQuadric(quadric);
}

/* Reads one GL_3D_COLOR vertex: x, y, z, r, g, b, a. */
static const GLfloat *vertex(const GLfloat *p)
{
  glColor4f(p[3], p[4], p[5], p[6]);
  glVertex3f(p[0], p[1], -p[2]);
  return p + 7;
}

static void cross(const GLfloat *p)
{
  glColor4f(p[3], p[4], p[5], p[6]);
  glBegin(GL_LINES);
  glVertex3f(p[0] - 4.0f, p[1], -p[2]);
  glVertex3f(p[0] + 4.0f, p[1], -p[2]);
  glVertex3f(p[0], p[1] - 4.0f, -p[2]);
  glVertex3f(p[0], p[1] + 4.0f, -p[2]);
  glEnd();
}

static void replay(GLint count)
{
  /* Window coordinates, and window z in [0, 1] as eye z in [-1, 0] (nearer is larger). */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, SIZE, 0.0, SIZE, 0.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glPointSize(3.0f);
  const GLfloat *p = buffer, *end = buffer + count;
  while (p < end) {
    const GLint token = (GLint)*p++;
    switch (token) {
    case GL_POLYGON_TOKEN: {
      const GLint n = (GLint)*p++;
      glBegin(GL_POLYGON);
      for (GLint i = 0; i < n; ++i) p = vertex(p);
      glEnd();
      break;
    }
    case GL_LINE_TOKEN:
    case GL_LINE_RESET_TOKEN:
      glBegin(GL_LINES);
      p = vertex(p);
      p = vertex(p);
      glEnd();
      break;
    case GL_POINT_TOKEN:
      glBegin(GL_POINTS);
      p = vertex(p);
      glEnd();
      break;
    case GL_PASS_THROUGH_TOKEN:
      glPointSize(*p++);
      break;
    case GL_BITMAP_TOKEN:
    case GL_DRAW_PIXEL_TOKEN:
    case GL_COPY_PIXEL_TOKEN:
      cross(p);
      p += 7;
      break;
    default:
      fprintf(stderr, "feedback_render: unknown token %d\n", token);
      exit(1);
    }
  }
}

static void draw(void)
{
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glFeedbackBuffer(VALUES, GL_3D_COLOR, buffer);
  glRenderMode(GL_FEEDBACK);
  scene();
  const GLint count = glRenderMode(GL_RENDER);
  if (count < 0) {
    fprintf(stderr, "feedback_render: the feedback buffer overflowed\n");
    exit(1);
  }
  replay(count);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, SIZE, SIZE, draw);
}
