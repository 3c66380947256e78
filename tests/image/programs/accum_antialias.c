/* The accumulation buffer (GL 1.5 specification, section 4.2.4) as the Red Book uses it for
 * scene antialiasing and depth of field (accanti.c, accpersp.c, dof.c): the scene is drawn
 * several times with the frustum jittered by a fraction of a pixel (or the eye moved around a
 * focal point), each picture added with glAccum(GL_ACCUM, 1/n) after a first GL_LOAD, and the
 * average returned with glAccum(GL_RETURN, 1).
 *   left:   lit spheres, a cylinder and a flat-shaded quadrilateral, antialiased with 8 jittered
 *           frusta; across its top a band made in the accumulation buffer alone, within the
 *           scissor box: glClearAccum and glClear, GL_MULT, GL_ADD, and GL_RETURN with a scale
 *   right:  a row of spheres at increasing distance, depth of field with 8 eye positions
 *           around a circle, in focus at the middle sphere
 * The jitter offsets are a rotated 8-sample grid computed here. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { SIZE = 200, SAMPLES = 8 };

static const double PI = 3.14159265358979;

static GLUquadric *quadric;

/* Sample i of a rotated grid, in pixels, within (-0.5, 0.5). */
static void jitter(int i, double *dx, double *dy)
{
  const double u = ((i % 4) + 0.5) / 4.0 - 0.5, v = ((i / 4) + 0.5) / 2.0 - 0.5;
  const double angle = 0.46;
  *dx = u * cos(angle) - v * sin(angle) * 0.5;
  *dy = u * sin(angle) + v * cos(angle) * 0.5;
}

/* glFrustum moved by (dx, dy) pixels, and the eye by (eyeX, eyeY) in the focal plane at
 * distance focus (the Red Book's accFrustum). */
static void jitteredFrustum(double left, double right, double bottom, double top, double near,
                            double far, double dx, double dy, double eyeX, double eyeY,
                            double focus)
{
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  const double xwsize = right - left, ywsize = top - bottom;
  const double ox = -(dx * xwsize / viewport[2] + eyeX * near / focus);
  const double oy = -(dy * ywsize / viewport[3] + eyeY * near / focus);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(left + ox, right + ox, bottom + oy, top + oy, near, far);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslated(-eyeX, -eyeY, 0.0);
}

static void material(float r, float g, float b)
{
  const GLfloat diffuse[4] = {r, g, b, 1.0f};
  const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
}

static void lights(void)
{
  const GLfloat position[4] = {2.0f, 3.0f, 4.0f, 0.0f};
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
}

static void antialiasedScene(void)
{
  lights();
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -6.0f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  material(0.9f, 0.3f, 0.2f);
  glPushMatrix();
  glTranslatef(-0.8f, 0.3f, 0.0f);
  gluSphere(quadric, 0.7, 16, 12);
  glPopMatrix();
  material(0.2f, 0.5f, 0.9f);
  glPushMatrix();
  glTranslatef(0.8f, -0.2f, 0.3f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(quadric, 0.35, 0.1, 1.2, 12, 2);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glShadeModel(GL_FLAT);
  glColor3f(1.0f, 0.9f, 0.3f);
  glBegin(GL_QUADS);
  glVertex3f(-1.2f, -1.4f, 0.8f);
  glVertex3f(1.3f, -1.1f, 0.6f);
  glVertex3f(1.1f, -0.9f, 0.5f);
  glVertex3f(-1.3f, -1.15f, 0.7f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glPopMatrix();
}

static void antialiased(void)
{
  glViewport(0, 0, SIZE, SIZE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, SIZE, SIZE);
  for (int i = 0; i < SAMPLES; ++i) {
    double dx, dy;
    jitter(i, &dx, &dy);
    glClearColor(0.1f, 0.15f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    jitteredFrustum(-1.0, 1.0, -1.0, 1.0, 4.0, 10.0, dx, dy, 0.0, 0.0, 1.0);
    antialiasedScene();
    glAccum(i == 0 ? GL_LOAD : GL_ACCUM, 1.0f / SAMPLES);
  }
  glAccum(GL_RETURN, 1.0f);

  /* The band: (0.2, 0.5, 0.9) halved, plus 0.1, returned at 1.5 times. */
  glScissor(0, SIZE - 16, SIZE, 12);
  glClearAccum(0.2f, 0.5f, 0.9f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_MULT, 0.5f);
  glAccum(GL_ADD, 0.1f);
  glAccum(GL_RETURN, 1.5f);
  glDisable(GL_SCISSOR_TEST);
}

static void depthOfField(void)
{
  glViewport(SIZE, 0, SIZE, SIZE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(SIZE, 0, SIZE, SIZE);
  for (int i = 0; i < SAMPLES; ++i) {
    const double a = 2.0 * PI * i / SAMPLES;
    glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    jitteredFrustum(-0.6, 0.6, -0.6, 0.6, 2.0, 20.0, 0.0, 0.0, 0.12 * cos(a), 0.12 * sin(a), 6.5);
    lights();
    for (int k = 0; k < 5; ++k) {
      glPushMatrix();
      glTranslatef(-0.9f + 0.6f * (float)k, -0.35f + 0.2f * (float)k, -3.5f - 1.5f * (float)k);
      material(0.3f + 0.15f * (float)k, 0.8f - 0.12f * (float)k, 0.4f);
      gluSphere(quadric, 0.45, 20, 14);
      glPopMatrix();
    }
    glDisable(GL_LIGHTING);
    glAccum(i == 0 ? GL_LOAD : GL_ACCUM, 1.0f / SAMPLES);
  }
  glAccum(GL_RETURN, 1.0f);
  glDisable(GL_SCISSOR_TEST);
}

static void draw(void)
{
  quadric = gluNewQuadric();
  antialiased();
  depthOfField();
  gluDeleteQuadric(quadric);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 2 * SIZE, SIZE, draw);
}
