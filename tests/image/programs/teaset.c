/* glutSolidTeacup, glutSolidTeaspoon and their wire forms: freeglut 3's teacup and teaspoon,
 * lit and environment-mapped (GL_SPHERE_MAP texture generation, which follows the normals), with
 * wire ones beside them. The Mesa reference is freeglut's teaset (see reference_images/README.md);
 * glass tessellates the teacup and the teaspoon as freeglut does (8 x 8 points per patch as
 * triangles for the solid ones, 10 x 10 as line strips for the wire ones), with the same normals,
 * so both draw the same triangles and reflect the same texels. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/freeglut.h> /* the teacup and teaspoon are freeglut extensions */

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, ENVIRONMENT = 32 };

/* A sphere map of a room: a warm sky above a horizon band and a dark floor, with a window. */
static void environmentMap(void)
{
  static GLubyte texels[ENVIRONMENT][ENVIRONMENT][3];
  for (int y = 0; y < ENVIRONMENT; ++y)
    for (int x = 0; x < ENVIRONMENT; ++x) {
      GLubyte *t = texels[y][x];
      const int window = x >= 18 && x < 26 && y >= 20 && y < 28;
      if (window) {
        t[0] = 250; t[1] = 250; t[2] = 235;
      } else if (y >= 16) {
        t[0] = (GLubyte)(120 + 4 * (y - 16)); t[1] = (GLubyte)(110 + 3 * (y - 16)); t[2] = 160;
      } else {
        t[0] = (GLubyte)(40 + 3 * y); t[1] = (GLubyte)(30 + 2 * y); t[2] = 25;
      }
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, ENVIRONMENT, ENVIRONMENT, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {2.0f, 4.0f, 3.0f, 0.0f};
  static const GLfloat porcelain[4] = {0.95f, 0.93f, 0.9f, 1.0f};
  static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};

  glClearColor(0.14f, 0.12f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(35.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  gluLookAt(0.0, 2.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, porcelain);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60.0f);
  environmentMap();
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_2D);
  glPushMatrix();
  glTranslatef(-1.0f, 0.3f, 0.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
  glutSolidTeacup(1.6);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.2f, -0.75f, 1.0f);
  glRotatef(75.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(-20.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTeaspoon(2.4);
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);

  glDisable(GL_LIGHTING);
  glColor3f(0.9f, 0.75f, 0.45f);
  glPushMatrix();
  glTranslatef(1.35f, 0.55f, -0.5f);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(40.0f, 0.0f, 1.0f, 0.0f);
  glutWireTeacup(1.3);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.6f, -0.55f, 0.6f);
  glRotatef(-60.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
  glutWireTeaspoon(2.0);
  glPopMatrix();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
