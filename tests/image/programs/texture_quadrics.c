/* Textured quadrics and the exam's torus (study guide, section 4.1, item 3):
 *
 *   gluSphere     gluCylinder
 *   gluDisk       a torus with the centre of the map at its front
 *
 * The quadrics take their texture coordinates from GLU (gluQuadricTexture). The torus
 *   x = (R + r cos theta) sin phi,  y = r sin theta,  z = (R + r cos theta) cos phi
 * faces the viewer (on the +z axis) at phi = 0, theta = 0. With
 *   s = 1/2 + phi / (2 pi),  t = 1/2 + theta / (2 pi),  phi, theta in [-pi, pi],
 * s and t stay in [0, 1] and the front point gets (s, t) = (1/2, 1/2): the bull's eye painted at
 * the centre of the texture appears right at the front of the torus (docs/texturing.md derives
 * this). The map is mipmapped and filtered trilinearly. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { PANEL = 220, TEX = 64, RINGS = 48, SIDES = 32 };

static const double PI = 3.14159265358979323846;

static void makeTexture(void)
{
  static GLubyte texels[TEX][TEX][3];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      GLubyte *t = texels[j][i];
      /* Quadrants of different colours, a grid, and a bull's eye at the centre. */
      const int right = i >= TEX / 2, top = j >= TEX / 2;
      t[0] = right ? 230 : 60;
      t[1] = top ? 200 : 90;
      t[2] = right == top ? 220 : 70;
      if (i % 8 == 0 || j % 8 == 0) t[0] = t[1] = t[2] = 250;
      const int dx = 2 * i + 1 - TEX, dy = 2 * j + 1 - TEX, d2 = dx * dx + dy * dy;
      if (d2 < 144) {
        const int ring = (int)sqrt((double)d2) / 4;
        t[0] = ring % 2 ? 255 : 200;
        t[1] = ring % 2 ? 255 : 0;
        t[2] = ring % 2 ? 255 : 0;
      }
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX, TEX, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

/* The torus point and normal for angles (phi, theta), with its (s, t). */
static void torusVertex(double R, double r, double phi, double theta)
{
  const double ring = R + r * cos(theta);
  glTexCoord2d(0.5 + phi / (2.0 * PI), 0.5 + theta / (2.0 * PI));
  glNormal3d(cos(theta) * sin(phi), sin(theta), cos(theta) * cos(phi));
  glVertex3d(ring * sin(phi), r * sin(theta), ring * cos(phi));
}

static void torus(double R, double r)
{
  for (int i = 0; i < RINGS; ++i) {
    const double phi0 = -PI + 2.0 * PI * i / RINGS, phi1 = -PI + 2.0 * PI * (i + 1) / RINGS;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= SIDES; ++j) {
      const double theta = -PI + 2.0 * PI * j / SIDES;
      torusVertex(R, r, phi1, theta);
      torusVertex(R, r, phi0, theta);
    }
    glEnd();
  }
}

static void panel(int index)
{
  glViewport((index % 2) * PANEL, (1 - index / 2) * PANEL, PANEL, PANEL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
}

static void draw(void)
{
  GLUquadric *quadric = gluNewQuadric();
  gluQuadricTexture(quadric, GL_TRUE);
  glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  {
    const GLfloat position[4] = {1.0f, 2.0f, 3.0f, 0.0f};
    const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLfloat ambient[4] = {0.35f, 0.35f, 0.35f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  }
  makeTexture();
  glEnable(GL_TEXTURE_2D);

  panel(0);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
  gluSphere(quadric, 1.4, 36, 24);

  panel(1);
  glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -1.2f);
  gluCylinder(quadric, 1.0, 0.7, 2.4, 36, 6);

  panel(2);
  glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
  gluDisk(quadric, 0.4, 1.6, 36, 6);

  panel(3);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  torus(1.25, 0.5);

  gluDeleteQuadric(quadric);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 2 * PANEL, 2 * PANEL, draw);
}
