/* The level-of-detail bias (OpenGL 1.4, section 3.8.8): lambda' = log2(rho) + clamp(bias of the
 * texture object + bias of the texture unit, +-GL_MAX_TEXTURE_LOD_BIAS). A floor receding to the
 * horizon with a mipmapped texture whose levels have distinct colours, GL_LINEAR_MIPMAP_NEAREST,
 * in four strips from left to right:
 *   no bias; the unit's bias -1 (glTexEnv GL_TEXTURE_FILTER_CONTROL); the texture's bias +1.5
 *   (glTexParameter GL_TEXTURE_LOD_BIAS); both, +1.5 and +0.5 = +2, on texture unit 1.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 200, STRIPS = 4 };

static GLuint textures[2];

static void makeTexture(GLuint name)
{
  static const GLubyte levelColors[8][3] = {{230, 230, 230}, {230, 60, 60}, {60, 200, 60},
                                            {60, 90, 230},   {230, 200, 40}, {200, 60, 200},
                                            {40, 200, 200},  {120, 120, 120}};
  static GLubyte texels[64 * 64][3];
  glBindTexture(GL_TEXTURE_2D, name);
  for (int level = 0, size = 64; size >= 1; ++level, size /= 2) {
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        /* The level's colour, with a darker checker so that the texture can be seen to move. */
        const int dark = ((i * 8 / size) + (j * 8 / size)) % 2 && size >= 8;
        for (int k = 0; k < 3; ++k)
          texels[j * size + i][k] = (GLubyte)(levelColors[level][k] * (dark ? 3 : 4) / 4);
      }
    }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void floorStrip(int strip)
{
  const float x0 = -2.0f + 4.0f * strip / STRIPS, x1 = -2.0f + 4.0f * (strip + 1) / STRIPS;
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
  glVertex3f(x0, -1.0f, -1.5f);
  glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
  glVertex3f(x1, -1.0f, -1.5f);
  glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 20.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 20.0f);
  glVertex3f(x1, -1.0f, -40.0f);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 20.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 20.0f);
  glVertex3f(x0, -1.0f, -40.0f);
  glEnd();
}

static void draw(void)
{
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -0.5, 0.5, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glGenTextures(2, textures);
  makeTexture(textures[0]);
  makeTexture(textures[1]);
  glColor3f(1.0f, 1.0f, 1.0f);

  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  floorStrip(0);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.0f);
  floorStrip(1);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
  floorStrip(2);
  glDisable(GL_TEXTURE_2D);

  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5f);
  floorStrip(3);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
