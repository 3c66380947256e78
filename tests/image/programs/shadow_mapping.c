/* Shadow mapping with depth textures (OpenGL 1.4, sections 3.8.1, 3.8.13 and 3.8.14;
 * GL_ARB_depth_texture and GL_ARB_shadow), as the classic two-pass technique does it:
 *  1. the scene is drawn from the light into the depth buffer (a 256 x 256 viewport, polygon
 *     offset against self-shadowing), which glCopyTexImage2D copies into a GL_DEPTH_COMPONENT
 *     texture;
 *  2. the scene is drawn from the eye, dimly lit; then again fully lit, with eye-linear texture
 *     coordinates that give each point's position in the light's clip space (bias * light
 *     projection * light view, the eye planes set under the camera's view matrix so that the GL
 *     applies its inverse), GL_TEXTURE_COMPARE_MODE GL_COMPARE_R_TO_TEXTURE with GL_LEQUAL, and
 *     GL_DEPTH_TEXTURE_MODE GL_ALPHA: the alpha test keeps the lit fragments the light sees.
 * A ring, a sphere and a box over a floor; in the corner, the depth texture itself drawn as a
 * luminance texture (GL_TEXTURE_COMPARE_MODE GL_NONE). Nearest filtering, so that each
 * comparison is of one texel. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, MAP = 256 };

static const GLfloat light_position[4] = {3.0f, 6.0f, 2.5f, 1.0f};

static void box(float x, float y, float z, float half)
{
  static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const int v[6][4][3] = {
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
      {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
      {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
      {{-1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}},
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
      {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  int f, k;
  glBegin(GL_QUADS);
  for (f = 0; f < 6; ++f) {
    glNormal3fv(n[f]);
    for (k = 0; k < 4; ++k)
      glVertex3f(x + half * (float)v[f][k][0], y + half * (float)v[f][k][1], z + half * (float)v[f][k][2]);
  }
  glEnd();
}

static void scene(GLUquadric *quadric)
{
  int i, j;
  /* The floor, in strips so that per-vertex lighting varies over it. */
  glColor3f(0.75f, 0.72f, 0.65f);
  glNormal3f(0.0f, 1.0f, 0.0f);
  for (j = 0; j < 8; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= 8; ++i) {
      glVertex3f(-4.0f + (float)i, 0.0f, -4.0f + (float)(j + 1));
      glVertex3f(-4.0f + (float)i, 0.0f, -4.0f + (float)j);
    }
    glEnd();
  }
  glColor3f(0.85f, 0.3f, 0.25f);
  glPushMatrix();
  glTranslatef(-0.8f, 1.6f, 0.2f);
  glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(quadric, 0.7, 0.7, 0.35, 24, 1);
  gluDisk(quadric, 0.3, 0.7, 24, 2);
  glPopMatrix();
  glColor3f(0.3f, 0.55f, 0.85f);
  glPushMatrix();
  glTranslatef(1.2f, 0.9f, -0.6f);
  gluSphere(quadric, 0.8, 24, 16);
  glPopMatrix();
  glColor3f(0.4f, 0.75f, 0.35f);
  box(0.3f, 0.45f, 1.6f, 0.45f);
}

static void light_view(void)
{
  gluLookAt(light_position[0], light_position[1], light_position[2], 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
}

static void draw(void)
{
  static const GLfloat ambient_only[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat dim[4] = {0.18f, 0.18f, 0.2f, 1.0f};
  GLfloat light_matrix[16], row[4];
  GLUquadric *quadric = gluNewQuadric();
  GLuint map;
  int i;

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient_only);

  /* Pass 1: depth from the light. */
  glViewport(0, 0, MAP, MAP);
  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, 1.0, 3.0, 12.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  light_view();
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  scene(quadric);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  glGenTextures(1, &map);
  glBindTexture(GL_TEXTURE_2D, map);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, MAP, MAP, 0);

  /* The texture matrix of the lookup: bias * light projection * light view. */
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  gluPerspective(60.0, 1.0, 3.0, 12.0);
  light_view();
  glGetFloatv(GL_TEXTURE_MATRIX, light_matrix);
  glLoadIdentity();

  /* Pass 2: the eye's view, dim. */
  glViewport(0, 0, WIDTH, HEIGHT);
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(-2.5, 5.0, 7.5, 0.0, 0.4, 0.0, 0.0, 1.0, 0.0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, dim);
  glLightfv(GL_LIGHT0, GL_SPECULAR, ambient_only);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  scene(quadric);

  /* Pass 3: fully lit where the light sees the point. The eye planes are the rows of the light
   * matrix, given under the camera's view, so that they act on world coordinates. */
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  for (i = 0; i < 4; ++i) {
    row[0] = light_matrix[i];
    row[1] = light_matrix[4 + i];
    row[2] = light_matrix[8 + i];
    row[3] = light_matrix[12 + i];
    glTexGenfv(GL_S + i, GL_EYE_PLANE, row);
    glTexGeni(GL_S + i, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  }
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glEnable(GL_TEXTURE_GEN_Q);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glDepthFunc(GL_LEQUAL);
  scene(quadric);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glDisable(GL_TEXTURE_GEN_Q);
  glDisable(GL_LIGHTING);
  glDepthFunc(GL_LESS);

  /* The depth texture itself, as luminance, in the lower left corner. */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(4.0f, 4.0f);
  glTexCoord2f(1.0f, 0.0f);
  glVertex2f(100.0f, 4.0f);
  glTexCoord2f(1.0f, 1.0f);
  glVertex2f(100.0f, 100.0f);
  glTexCoord2f(0.0f, 1.0f);
  glVertex2f(4.0f, 100.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &map);
  gluDeleteQuadric(quadric);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
