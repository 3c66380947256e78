/* GLU quadrics as a homework scene uses them: a lit, textured globe (gluQuadricTexture with a
 * procedural latitude-longitude texture, GL_MODULATE, smooth normals), a flat-shaded lit cylinder
 * (GLU_FLAT normals) standing on a lit disc, a wireframe cone (GLU_LINE) and a partial disc drawn
 * as GLU_SILHOUETTE, with GLU_INSIDE orientation on a cylinder seen from inside, and a textured
 * partial disc. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static GLubyte map[32][64][3];

static void makeMap(void)
{
  int i, j;
  for (i = 0; i < 32; ++i) {
    for (j = 0; j < 64; ++j) {
      const int land = ((i * 5 + j * 3) % 17) < 7 && i > 3 && i < 28;
      const int grid = (i % 8 == 0) || (j % 8 == 0);
      map[i][j][0] = (GLubyte)(grid ? 255 : land ? 60 : 20);
      map[i][j][1] = (GLubyte)(grid ? 255 : land ? 160 : 60);
      map[i][j][2] = (GLubyte)(grid ? 255 : land ? 40 : 200);
    }
  }
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {3.0f, 4.0f, 5.0f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat copper[4] = {0.8f, 0.45f, 0.2f, 1.0f};
  static const GLfloat slate[4] = {0.35f, 0.4f, 0.45f, 1.0f};
  static const GLfloat teal[4] = {0.2f, 0.7f, 0.7f, 1.0f};
  GLUquadric *q = gluNewQuadric();
  GLuint texture;

  makeMap();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, map);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 3.0, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);

  /* Globe. */
  glPushMatrix();
  glTranslatef(-2.0f, 1.0f, 0.0f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(200.0f, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  gluQuadricTexture(q, GL_TRUE);
  gluSphere(q, 1.3, 36, 18);
  glDisable(GL_TEXTURE_2D);
  gluQuadricTexture(q, GL_FALSE);
  glPopMatrix();

  /* Flat-shaded cylinder on a disc. */
  glMaterialfv(GL_FRONT, GL_SPECULAR, slate);
  glPushMatrix();
  glTranslatef(1.5f, -1.2f, 0.5f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, slate);
  gluDisk(q, 0.0, 1.4, 24, 3);
  gluQuadricNormals(q, GLU_FLAT);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, copper);
  gluCylinder(q, 0.6, 0.4, 1.8, 12, 3);
  gluQuadricNormals(q, GLU_SMOOTH);
  glPopMatrix();

  /* Inside of a tube: GLU_INSIDE normals, cut open by looking down into it. */
  glPushMatrix();
  glTranslatef(3.2f, 1.2f, -1.5f);
  glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
  gluQuadricOrientation(q, GLU_INSIDE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, teal);
  gluCylinder(q, 0.7, 0.7, 1.0, 24, 1);
  gluQuadricOrientation(q, GLU_OUTSIDE);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Wire cone and silhouette disc. */
  glColor3f(1.0f, 1.0f, 0.5f);
  gluQuadricDrawStyle(q, GLU_LINE);
  glPushMatrix();
  glTranslatef(-0.2f, -1.5f, 2.0f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(q, 0.6, 0.0, 1.2, 10, 4);
  glPopMatrix();
  gluQuadricDrawStyle(q, GLU_SILHOUETTE);
  glColor3f(1.0f, 0.4f, 0.4f);
  glPushMatrix();
  glTranslatef(-3.0f, -1.6f, 1.5f);
  glRotatef(-75.0f, 1.0f, 0.0f, 0.0f);
  gluPartialDisk(q, 0.4, 0.9, 20, 3, 30.0, 250.0);
  glPopMatrix();

  /* Textured partial disc, filled. */
  gluQuadricDrawStyle(q, GLU_FILL);
  gluQuadricTexture(q, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPushMatrix();
  glTranslatef(0.4f, 2.0f, -2.0f);
  gluPartialDisk(q, 0.3, 1.0, 24, 4, -45.0, 200.0);
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
  gluDeleteQuadric(q);
  glDeleteTextures(1, &texture);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
