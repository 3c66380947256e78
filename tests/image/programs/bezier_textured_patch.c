/* A bicubic patch textured through GL_MAP2_TEXTURE_COORD_2 (section 5.1 of the GL 1.5
 * specification): the texture coordinate map is bilinear, 2 x 2 control points from (0, 0) to
 * (3, 2), so the checkerboard repeats three times along u and twice along v and follows the
 * surface's parametrisation. A second copy gets its colour from GL_MAP2_COLOR_4 (a bilinear
 * colour map whose domain [-0.5, 1.5]^2 is larger than the vertex map's) and is drawn by
 * glEvalMesh2(GL_LINE) over the rows 2 to 10 of a 12 x 12 grid. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, TEXTURE = 32 };

static const GLfloat surface[4][4][3] = {
    {{-1.5f, -1.5f, 0.0f}, {-0.5f, -1.5f, 0.8f}, {0.5f, -1.5f, -0.6f}, {1.5f, -1.5f, 0.2f}},
    {{-1.5f, -0.5f, 0.6f}, {-0.5f, -0.5f, 1.4f}, {0.5f, -0.5f, 0.2f}, {1.5f, -0.5f, -0.4f}},
    {{-1.5f, 0.5f, -0.5f}, {-0.5f, 0.5f, 0.3f}, {0.5f, 0.5f, 1.6f}, {1.5f, 0.5f, 0.4f}},
    {{-1.5f, 1.5f, 0.2f}, {-0.5f, 1.5f, -0.8f}, {0.5f, 1.5f, 0.5f}, {1.5f, 1.5f, 1.0f}}};

static void checkerTexture(void)
{
  static GLubyte texels[TEXTURE][TEXTURE][3];
  for (int y = 0; y < TEXTURE; ++y)
    for (int x = 0; x < TEXTURE; ++x) {
      const int dark = ((x / 8) + (y / 8)) % 2;
      texels[y][x][0] = dark ? 40 : 240;
      texels[y][x][1] = dark ? 70 : 200;
      texels[y][x][2] = dark ? 150 : 90;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEXTURE, TEXTURE, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

static void draw(void)
{
  static const GLfloat texCoords[2][2][2] = {{{0.0f, 0.0f}, {0.0f, 2.0f}}, {{3.0f, 0.0f}, {3.0f, 2.0f}}};
  static const GLfloat colors[2][2][4] = {{{1.0f, 0.2f, 0.2f, 1.0f}, {0.2f, 1.0f, 0.2f, 1.0f}},
                                          {{0.2f, 0.3f, 1.0f, 1.0f}, {1.0f, 1.0f, 0.3f, 1.0f}}};

  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, -6.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);

  glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &surface[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);

  checkerTexture();
  glEnable(GL_TEXTURE_2D);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 2, 2, &texCoords[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glMapGrid2f(24, 0.0f, 1.0f, 24, 0.0f, 1.0f);
  glPushMatrix();
  glTranslatef(-1.3f, 0.3f, 0.0f);
  glScalef(0.85f, 0.85f, 0.85f);
  glEvalMesh2(GL_FILL, 0, 24, 0, 24);
  glPopMatrix();
  glDisable(GL_MAP2_TEXTURE_COORD_2);
  glDisable(GL_TEXTURE_2D);

  /* The colour map covers [-0.5, 1.5]^2; the vertex map [0, 1]^2. */
  glMap2f(GL_MAP2_COLOR_4, -0.5f, 1.5f, 8, 2, -0.5f, 1.5f, 4, 2, &colors[0][0][0]);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(12, 0.0f, 1.0f, 12, 0.0f, 1.0f);
  glPushMatrix();
  glTranslatef(1.9f, 0.6f, 0.3f);
  glScalef(0.75f, 0.75f, 0.75f);
  glEvalMesh2(GL_LINE, 0, 12, 2, 10);
  glPopMatrix();
  glDisable(GL_MAP2_COLOR_4);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
