/* Texture coordinate generation (glTexGen, spec 2.11.4) on lit spheres:
 *
 *   OBJECT_LINEAR (1D stripes)    EYE_LINEAR (the same stripes)
 *   SPHERE_MAP (a sky and ground) projective: s, t, r, q all EYE_LINEAR, then a projector's
 *                                 matrices on the texture stack, q divides
 *
 * The two spheres of the top row are the same sphere under the same rotation: OBJECT_LINEAR
 * stripes follow the object (they tilt with it), EYE_LINEAR stripes stay upright in eye space. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { PANEL = 200, STRIPES = 32, ENV = 64, SLIDE = 32 };

static GLuint stripes1D, environment2D, slide2D;

static void makeTextures(void)
{
  static GLubyte stripes[STRIPES][3];
  static GLubyte env[ENV][ENV][3];
  static GLubyte slide[SLIDE][SLIDE][3];
  for (int i = 0; i < STRIPES; ++i) {
    const int band = i / 4;
    stripes[i][0] = band % 2 ? 250 : 40;
    stripes[i][1] = band % 2 ? 200 : 60;
    stripes[i][2] = band % 2 ? 60 : 200;
  }
  for (int j = 0; j < ENV; ++j) {
    for (int i = 0; i < ENV; ++i) {
      GLubyte *t = env[j][i];
      if (j >= ENV / 2) { /* sky: blue getting lighter towards the horizon */
        t[0] = (GLubyte)(60 + 2 * (ENV - j));
        t[1] = (GLubyte)(110 + 2 * (ENV - j));
        t[2] = 240;
      } else { /* ground: a brown checkerboard */
        const int check = ((i / 8) + (j / 8)) % 2;
        t[0] = check ? 150 : 90;
        t[1] = check ? 110 : 60;
        t[2] = check ? 60 : 30;
      }
    }
  }
  for (int j = 0; j < SLIDE; ++j) {
    for (int i = 0; i < SLIDE; ++i) {
      const int ring = ((i - 16) * (i - 16) + (j - 16) * (j - 16)) / 40;
      slide[j][i][0] = ring % 2 ? 255 : 30;
      slide[j][i][1] = ring % 2 ? 120 : 220;
      slide[j][i][2] = (GLubyte)(8 * i);
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &stripes1D);
  glBindTexture(GL_TEXTURE_1D, stripes1D);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, STRIPES, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glGenTextures(1, &environment2D);
  glBindTexture(GL_TEXTURE_2D, environment2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, ENV, ENV, 0, GL_RGB, GL_UNSIGNED_BYTE, env);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glGenTextures(1, &slide2D);
  glBindTexture(GL_TEXTURE_2D, slide2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, SLIDE, SLIDE, 0, GL_RGB, GL_UNSIGNED_BYTE, slide);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  /* Outside the slide the projector's light is a plain grey: the border colour. */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  {
    const GLfloat grey[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, grey);
  }
}

static void panel(int index)
{
  glViewport((index % 2) * PANEL, (1 - index / 2) * PANEL, PANEL, PANEL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void sphere(GLUquadric *quadric)
{
  gluSphere(quadric, 1.0, 40, 30);
}

static void draw(void)
{
  GLUquadric *quadric = gluNewQuadric();
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  {
    const GLfloat position[4] = {2.0f, 3.0f, 4.0f, 0.0f};
    const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  }
  makeTextures();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  /* OBJECT_LINEAR and EYE_LINEAR: s = 1.5 x + 0.5 z + 0.5 in the plane's space. */
  const GLfloat plane[4] = {1.5f, 0.0f, 0.5f, 0.5f};
  for (int k = 0; k < 2; ++k) {
    panel(k);
    glEnable(GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_1D, stripes1D);
    const GLint mode = k == 0 ? GL_OBJECT_LINEAR : GL_EYE_LINEAR;
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
    /* Eye planes are taken through the modelview matrix of this moment: the identity here. */
    glTexGenfv(GL_S, k == 0 ? GL_OBJECT_PLANE : GL_EYE_PLANE, plane);
    glEnable(GL_TEXTURE_GEN_S);
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(35.0f, 0.0f, 0.0f, 1.0f);
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    sphere(quadric);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_1D);
  }

  /* SPHERE_MAP: a mirror ball reflecting the sky-and-ground map. */
  panel(2);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, environment2D);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(0.0f, 0.0f, -4.0f);
  sphere(quadric);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);

  /* Projective texturing: the eye planes are the identity rows (so (s, t, r, q) is the eye
   * position), and the texture matrix takes eye space to the projector's [0, 1] square. The
   * slide falls on the sphere and on a floor behind it. */
  panel(3);
  {
    static const GLfloat rows[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    static const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
    static const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                      GL_TEXTURE_GEN_Q};
    for (int c = 0; c < 4; ++c) {
      glTexGeni(coords[c], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
      glTexGenfv(coords[c], GL_EYE_PLANE, rows[c]);
      glEnable(enables[c]);
    }
  }
  glBindTexture(GL_TEXTURE_2D, slide2D);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  gluPerspective(25.0, 1.0, 1.0, 20.0);
  /* The projector stands up and to the left of the camera, aimed at the sphere. */
  gluLookAt(-1.5, 1.5, 0.5, 0.0, 0.0, -4.0, 0.0, 1.0, 0.0);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -4.0f);
  gluSphere(quadric, 0.8, 40, 30);
  glPopMatrix();
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);
  glVertex3f(-3.0f, -3.0f, -6.0f);
  glVertex3f(3.0f, -3.0f, -6.0f);
  glVertex3f(3.0f, 3.0f, -6.0f);
  glVertex3f(-3.0f, 3.0f, -6.0f);
  glEnd();
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glDisable(GL_TEXTURE_GEN_Q);
  glDisable(GL_TEXTURE_2D);
  gluDeleteQuadric(quadric);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 2 * PANEL, 2 * PANEL, draw);
}
