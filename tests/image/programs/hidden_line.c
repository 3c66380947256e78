/* Hidden-line removal with glPolygonOffset, as the classic polygon-offset demo does it: each
 * object is drawn filled in the background colour (or lit) pushed back with
 * GL_POLYGON_OFFSET_FILL, then drawn again with glPolygonMode(GL_LINE) in black, so that only the
 * visible edges show and no line is lost to depth fighting. Left: a lit sphere with black
 * outlines (factor 1, units 1). Middle: a wireframe torus with its hidden lines removed
 * (background-coloured fill, factor 2, units 2). Right: the same torus with lines pulled forward
 * instead (GL_POLYGON_OFFSET_LINE with negative offsets) over a lit fill, back faces culled, and
 * a small quad with GL_POLYGON_OFFSET_POINT drawn as points.
 *
 * Not glPolygonMode(GL_FRONT, GL_LINE) with back faces left filled: Mesa 22.3's draw module then
 * takes the offset of a whole batch of triangles from the mode of its first triangle (a back
 * face, GL_FILL, no line offset), so front-face lines of such batches lose their offset and half
 * their pixels; glass offsets every line as the specification says. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 180 };

static void draw(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat green[4] = {0.3f, 0.8f, 0.4f, 1.0f};
  static const GLfloat violet[4] = {0.6f, 0.4f, 0.9f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(30.0, (double)WIDTH / HEIGHT, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHT0);
  gluLookAt(0.0, 2.0, 10.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  /* Left: lit sphere and its outline. */
  glPushMatrix();
  glTranslatef(-3.6f, 0.0f, 0.0f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  gluSphere(q, 1.2, 16, 10);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_LIGHTING);
  glColor3f(0.0f, 0.0f, 0.0f);
  gluQuadricDrawStyle(q, GLU_LINE);
  gluSphere(q, 1.2, 16, 10);
  gluQuadricDrawStyle(q, GLU_FILL);
  glPopMatrix();

  /* Middle: hidden-line torus. */
  glPushMatrix();
  glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glutSolidTorus(0.4, 1.0, 10, 20);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColor3f(0.0f, 0.0f, 0.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glutSolidTorus(0.4, 1.0, 10, 20);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glPopMatrix();

  /* Right: lines pulled forward over a lit fill. */
  glPushMatrix();
  glTranslatef(3.6f, 0.0f, 0.0f);
  glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, violet);
  glutSolidTorus(0.4, 1.0, 10, 20);
  glDisable(GL_LIGHTING);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glPolygonOffset(-1.0f, -1.0f);
  glColor3f(0.1f, 0.1f, 0.3f);
  glEnable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glutSolidTorus(0.4, 1.0, 10, 20);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_LINE);

  glEnable(GL_POLYGON_OFFSET_POINT);
  glPolygonOffset(-1.0f, -4.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3.0f);
  glColor3f(0.9f, 0.1f, 0.1f);
  glBegin(GL_QUADS);
  glVertex3f(-0.4f, -0.4f, 1.4f);
  glVertex3f(0.4f, -0.4f, 1.4f);
  glVertex3f(0.4f, 0.4f, 1.4f);
  glVertex3f(-0.4f, 0.4f, 1.4f);
  glEnd();
  glPointSize(1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_POLYGON_OFFSET_POINT);
  glPopMatrix();
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
