/* GL_GLASS_bump_map, glass's bump-mapping extension (docs/texturing.md), on two lit spheres: the
 * left one with a height map of raised tiles, the right one without. Both are lit per fragment
 * (GL_PHONG_WIN), which bump mapping needs, and carry the same colour texture.
 *
 *   cc docs/examples/bump_map.c $(pkg-config --cflags --libs glass) -lm -o bump_map
 *   ./bump_map bump_map.png
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <glass/context.h>

#include <math.h>
#include <stdio.h>

enum { WIDTH = 480, HEIGHT = 240, TEX = 128, TILES = 8 };

/* Heights: raised square tiles with rounded edges, separated by grooves. */
static void makeHeightMap(GLuint name)
{
  static GLubyte heights[TEX][TEX];
  for (int j = 0; j < TEX; ++j)
    for (int i = 0; i < TEX; ++i) {
      const float u = (float)(i % (TEX / TILES)) / (TEX / TILES) - 0.5f;
      const float v = (float)(j % (TEX / TILES)) / (TEX / TILES) - 0.5f;
      const float edge = fmaxf(fabsf(u), fabsf(v));  /* 0 at a tile's centre, 0.5 at its edge */
      const float h = edge < 0.35f ? 1.0f : edge > 0.45f ? 0.0f : (0.45f - edge) / 0.1f;
      heights[j][i] = (GLubyte)(255.0f * h);
    }
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, TEX, TEX, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, heights);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void makeColorTexture(GLuint name)
{
  static GLubyte texels[TEX][TEX][3];
  for (int j = 0; j < TEX; ++j)
    for (int i = 0; i < TEX; ++i) {
      const int tile = (i / (TEX / TILES)) + (j / (TEX / TILES));
      texels[j][i][0] = (GLubyte)(tile % 2 ? 200 : 150);
      texels[j][i][1] = (GLubyte)(tile % 2 ? 120 : 160);
      texels[j][i][2] = (GLubyte)(tile % 2 ? 90 : 200);
    }
  glBindTexture(GL_TEXTURE_2D, name);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

int main(int argc, char **argv)
{
  GlassContext *ctx = glassCreateContext(WIDTH, HEIGHT);
  if (argc != 2 || !ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "usage: %s OUTPUT.png\n", argv[0]);
    return 2;
  }
  GLuint textures[2];
  glGenTextures(2, textures);
  makeHeightMap(textures[0]);
  makeColorTexture(textures[1]);

  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  gluPerspective(30.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  const GLfloat light[4] = {-2.0f, 2.0f, 3.0f, 0.0f};
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_PHONG_WIN);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexEnvi(GL_BUMP_MAP_GLASS, GL_BUMP_MAP_TEXTURE_GLASS, (GLint)textures[0]);
  glTexEnvf(GL_BUMP_MAP_GLASS, GL_BUMP_SCALE_GLASS, 0.02f);

  GLUquadric *sphere = gluNewQuadric();
  gluQuadricTexture(sphere, GL_TRUE);
  for (int k = 0; k < 2; ++k) {
    if (k == 0) glEnable(GL_BUMP_MAP_GLASS); else glDisable(GL_BUMP_MAP_GLASS);
    glLoadIdentity();
    glTranslatef(k == 0 ? -1.1f : 1.1f, 0.0f, -6.0f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    gluSphere(sphere, 1.0, 64, 32);
  }
  gluDeleteQuadric(sphere);

  const int ok = glassWritePNG(ctx, argv[1]);
  glassDestroyContext(ctx);
  return ok ? 0 : 1;
}
