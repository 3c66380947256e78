/* Cube map textures (OpenGL 1.3, section 3.8.6) and the GL_REFLECTION_MAP and GL_NORMAL_MAP
 * texture coordinate generation (2.11.4). The six faces are coloured differently, each with a
 * grid and a mark in its +s, +t corner, so that the face and its orientation show:
 *
 *   left:   a sphere with GL_REFLECTION_MAP on s, t and r (a mirror ball), the texture matrix
 *           turning the environment by 30 degrees about y
 *   middle: the same sphere with GL_NORMAL_MAP
 *   right:  a rotated cube in perspective whose vertices carry their own directions
 *           (glMultiTexCoord3f) on texture unit 1, over a 2D texture on unit 0
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { CELL = 200, FACE = 32, SLICES = 32, STACKS = 24 };

static const GLubyte faceColors[6][3] = {{230, 70, 60},  {70, 200, 220}, {90, 210, 80},
                                         {200, 80, 210}, {240, 220, 60}, {70, 90, 230}};

static void makeCubeMap(void)
{
  static GLubyte texels[FACE][FACE][3];
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < FACE; ++j) {
      for (int i = 0; i < FACE; ++i) {
        const int grid = (i % 8 == 0) || (j % 8 == 0);
        const int mark = i >= FACE - 8 && j >= FACE - 8;
        for (int k = 0; k < 3; ++k) {
          const int c = faceColors[face][k];
          texels[j][i][k] = (GLubyte)(mark ? 255 - c / 2 : grid ? c / 3 : c);
        }
      }
    }
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGB, FACE, FACE, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

static void makeStripes(void)
{
  static GLubyte stripes[8][8];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) stripes[j][i] = (GLubyte)((i + j) % 4 < 2 ? 255 : 150);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, stripes);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* A unit sphere with normals, by latitude and longitude. */
static void sphere(void)
{
  const float pi = 3.14159265f;
  for (int j = 0; j < STACKS; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= SLICES; ++i) {
      for (int k = 1; k >= 0; --k) {
        const float theta = pi * (float)(j + k) / STACKS - pi / 2, phi = 2 * pi * i / SLICES;
        const float x = cosf(theta) * sinf(phi), y = sinf(theta), z = cosf(theta) * cosf(phi);
        glNormal3f(x, y, z);
        glVertex3f(x, y, z);
      }
    }
    glEnd();
  }
}

static void viewport(int column)
{
  glViewport(column * CELL, 0, CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.2f);
}

static void generate(GLenum mode)
{
  for (GLenum coord = GL_S; coord <= GL_R; ++coord) glTexGeni(coord, GL_TEXTURE_GEN_MODE, (GLint)mode);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
}

static void cube(void)
{
  static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int faces[6][4] = {{1, 2, 6, 5}, {0, 4, 7, 3}, {3, 7, 6, 2},
                                  {0, 1, 5, 4}, {4, 5, 6, 7}, {0, 3, 2, 1}};
  static const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    for (int k = 0; k < 4; ++k) {
      const float* p = corners[faces[f][k]];
      glMultiTexCoord2f(GL_TEXTURE0, 2.0f * st[k][0], 2.0f * st[k][1]);
      glMultiTexCoord3f(GL_TEXTURE1, p[0], p[1], p[2]);
      glVertex3fv(p);
    }
  }
  glEnd();
}

static void draw(void)
{
  GLuint textures[2];
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glGenTextures(2, textures);
  glBindTexture(GL_TEXTURE_CUBE_MAP, textures[0]);
  makeCubeMap();
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  makeStripes();
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  viewport(0);
  glEnable(GL_TEXTURE_CUBE_MAP);
  generate(GL_REFLECTION_MAP);
  glMatrixMode(GL_TEXTURE);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
  sphere();
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  viewport(1);
  generate(GL_NORMAL_MAP);
  glRotatef(40.0f, 1.0f, 0.0f, 0.0f);
  sphere();
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glDisable(GL_TEXTURE_CUBE_MAP);

  viewport(2);
  glTranslatef(0.0f, 0.0f, -1.0f);
  glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-40.0f, 0.0f, 1.0f, 0.0f);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_CUBE_MAP, textures[0]);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  cube();
  glDisable(GL_TEXTURE_CUBE_MAP);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 3 * CELL, CELL, draw);
}
