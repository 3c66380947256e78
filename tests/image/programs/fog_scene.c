/* Fog, as in the classic fog demo: a row of lit red tori receding into the distance, drawn three
 * times side by side (three viewports, each cleared with glScissor to its own background) with
 * GL_EXP (density 0.35), GL_EXP2 (density 0.35) and GL_LINEAR (start 1, end 8), the fog colour
 * grey-blue in each and the clear colour equal to it, as programs do so that far objects fade into
 * the background. A ground line of unlit GL_LINES and a floor quad take the fog too. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 200 };

static void scene(void)
{
  static const GLfloat red[4] = {0.9f, 0.15f, 0.1f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  int i;

  glDisable(GL_LIGHTING);
  glColor3f(0.2f, 0.5f, 0.2f);
  glBegin(GL_QUADS);
  glVertex3f(-3.0f, -1.0f, 0.0f);
  glVertex3f(3.0f, -1.0f, 0.0f);
  glVertex3f(3.0f, -1.0f, -12.0f);
  glVertex3f(-3.0f, -1.0f, -12.0f);
  glEnd();
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINES);
  for (i = 0; i <= 12; ++i) {
    glVertex3f(-3.0f, -0.99f, -(float)i);
    glVertex3f(3.0f, -0.99f, -(float)i);
  }
  glEnd();

  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 50.0f);
  for (i = 0; i < 5; ++i) {
    glPushMatrix();
    glTranslatef(-1.2f + 0.9f * (float)i, 0.0f, -1.5f - 2.0f * (float)i);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    glutSolidTorus(0.2, 0.5, 12, 24);
    glPopMatrix();
  }
}

static void panel(int index, GLint mode)
{
  static const GLfloat fogColour[4] = {0.5f, 0.55f, 0.6f, 1.0f};
  const int x = index * WIDTH / 3;
  glViewport(x, 0, WIDTH / 3, HEIGHT);
  glScissor(x, 0, WIDTH / 3, HEIGHT);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(fogColour[0], fogColour[1], fogColour[2], fogColour[3]);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);

  glFogi(GL_FOG_MODE, mode);
  glFogfv(GL_FOG_COLOR, fogColour);
  glFogf(GL_FOG_DENSITY, 0.35f);
  glFogf(GL_FOG_START, 1.0f);
  glFogf(GL_FOG_END, 8.0f);
  glHint(GL_FOG_HINT, GL_DONT_CARE);
  glEnable(GL_FOG);
  scene();
  glDisable(GL_FOG);
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {0.5f, 0.75f, 1.5f, 0.0f};

  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)(WIDTH / 3) / HEIGHT, 0.5, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHT0);

  panel(0, GL_EXP);
  panel(1, GL_EXP2);
  panel(2, GL_LINEAR);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
