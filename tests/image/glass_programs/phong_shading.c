/* Per-pixel lighting, glass's GL_WIN_phong_shading extension (docs/lighting.md): with
 * glShadeModel(GL_PHONG_WIN) the lighting equation is evaluated at every fragment from the
 * interpolated eye-space position and (renormalized) normal, instead of at the vertices.
 *
 * Left column GL_SMOOTH (Gouraud), right column GL_PHONG_WIN, same scene:
 *   top     a single large quad lit by a spotlight close above it: Gouraud only sees the four
 *           corners, which the cone misses, so the quad stays at its ambient level; per pixel,
 *           the spot's round pool of light appears with its soft edge.
 *   bottom  a coarse sphere (gluSphere 12 x 8) with a tight highlight (shininess 60) and a
 *           two-coloured light: Gouraud smears the highlight along the facets' edges, per pixel
 *           it is round, and the silhouette keeps the sphere's polygons either way.
 * glass-only: the reference image is a reviewed glass render (reference_images/README.md). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 400 };

static void floorQuad(void)
{
  glNormal3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);
  glVertex3f(-1.4f, 0.0f, 1.1f);
  glVertex3f(1.4f, 0.0f, 1.1f);
  glVertex3f(1.4f, 0.0f, -1.1f);
  glVertex3f(-1.4f, 0.0f, -1.1f);
  glEnd();
}

static void scene(GLUquadric *q, GLenum shading)
{
  static const GLfloat spot[4] = {0.0f, 1.1f, 0.0f, 1.0f};
  static const GLfloat down[3] = {0.0f, -1.0f, 0.0f};
  static const GLfloat warm[4] = {1.0f, 0.85f, 0.6f, 1.0f};
  static const GLfloat floorColor[4] = {0.5f, 0.6f, 0.7f, 1.0f};
  static const GLfloat sphereColor[4] = {0.75f, 0.2f, 0.25f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat none[4] = {0.0f, 0.0f, 0.0f, 1.0f};

  glShadeModel(shading);

  /* Top: the floor under a spotlight (LIGHT1 only). */
  glDisable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, 0.0f);
  glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
  glLightfv(GL_LIGHT1, GL_POSITION, spot);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, down);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 40.0f);
  glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 4.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floorColor);
  glMaterialfv(GL_FRONT, GL_SPECULAR, none);
  floorQuad();
  glPopMatrix();

  /* Bottom: the coarse sphere (LIGHT0 only). */
  glDisable(GL_LIGHT1);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, sphereColor);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
  glPushMatrix();
  glTranslatef(0.0f, -1.3f, 0.0f);
  glRotatef(-80.0f, 1.0f, 0.0f, 0.0f);
  gluSphere(q, 0.95, 12, 8);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat direction[4] = {-1.0f, 1.0f, 1.5f, 0.0f};
  static const GLfloat bluish[4] = {0.8f, 0.85f, 1.0f, 1.0f};
  static const GLfloat ambient[4] = {0.3f, 0.3f, 0.3f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, direction); /* in eye coordinates */
  glLightfv(GL_LIGHT0, GL_DIFFUSE, bluish);
  glLightfv(GL_LIGHT0, GL_SPECULAR, bluish);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glTranslatef(0.0f, 0.0f, -6.5f);
  glEnable(GL_LIGHTING);

  glEnable(GL_NORMALIZE); /* both halves are scaled down */

  glPushMatrix();
  glTranslatef(-1.2f, 0.0f, 0.0f);
  glScalef(0.8f, 0.8f, 0.8f);
  scene(q, GL_SMOOTH);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.2f, 0.0f, 0.0f);
  glScalef(0.8f, 0.8f, 0.8f);
  scene(q, GL_PHONG_WIN);
  glPopMatrix();
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
