/* What the rest of the pipeline does to glDrawPixels and glBitmap (OpenGL 1.5 sections 2.13,
 * 3.6.5 and 3.7): their fragments take the raster position's depth and texture coordinates and
 * pass through texturing and every per-fragment test like a polygon's, and the raster colour is
 * computed by lighting when lighting is on. Programs meet this when they draw a sprite or a label
 * into a 3D scene without turning their scene state off first.
 *
 * A floor receding into linear fog (start 2, end 14) and a pillar, in perspective. Over them:
 *   - a row of sprites (an RGBA disc whose corners have alpha 0), drawn with glDrawPixels at
 *     raster positions 3 to 12 units away, fog off: the alpha test cuts their corners, and the
 *     depth test hides the fourth, which lies behind the pillar, and the columns of the fifth
 *     that overlap the pillar (an image has one depth, the raster position's);
 *   - labels from glBitmap with lighting on: the raster colour is the lit colour of the current
 *     material (red diffuse, light from the left) and the current normal, not the glColor, and
 *     changes with the normal given before each glRasterPos;
 *   - the same sprite with GL_TEXTURE_2D left on (a 2 x 2 texture of four colours, GL_MODULATE):
 *     each copy is modulated by the one texel at the texture coordinates glRasterPos captured,
 *     set by glTexCoord before it; a bitmap drawn with the same texture on, its set bits
 *     textured the same way.
 * Fog on pixel rectangles (the raster distance is their fog coordinate) and raster texture
 * coordinates that differ from the current ones (texgen, or glTexCoord after glRasterPos) are
 * left to tests/unit/pixels_fragment_state_test.cpp: Mesa 22.3 neither fogs pixel rectangles nor
 * textures them with the raster position's coordinates (it takes the current ones). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, SPRITE = 24 };

static GLubyte sprite[SPRITE][SPRITE][4];

static void makeSprite(void)
{
  for (int j = 0; j < SPRITE; ++j) {
    for (int i = 0; i < SPRITE; ++i) {
      const int dx = 2 * i - (SPRITE - 1), dy = 2 * j - (SPRITE - 1);
      const int inside = dx * dx + dy * dy <= (SPRITE - 2) * (SPRITE - 2);
      GLubyte *p = sprite[j][i];
      p[0] = (GLubyte)(255 - 6 * j);
      p[1] = (GLubyte)(120 + 5 * i);
      p[2] = (GLubyte)(((i / 4 + j / 4) & 1) ? 255 : 60);
      p[3] = inside ? 255 : 0;
    }
  }
}

/* A 16 x 12 glyph: a bold arrow. */
static const GLubyte arrow[12 * 2] = {
    0x00, 0x00, 0x01, 0x80, 0x01, 0xC0, 0x01, 0xE0, 0xFF, 0xF0, 0xFF, 0xF8,
    0xFF, 0xF8, 0xFF, 0xF0, 0x01, 0xE0, 0x01, 0xC0, 0x01, 0x80, 0x00, 0x00};

static void scene(void)
{
  /* The floor, y = 0, from z = 1 to z = -30, as strips so the fog shows along it. */
  glColor3f(0.3f, 0.7f, 0.35f);
  glBegin(GL_QUAD_STRIP);
  for (int k = 0; k <= 31; ++k) {
    glColor3f((k & 1) ? 0.3f : 0.45f, 0.7f, 0.35f);
    glVertex3f(-6.0f, 0.0f, 1.0f - k);
    glVertex3f(6.0f, 0.0f, 1.0f - k);
  }
  glEnd();
  /* The pillar: a box from (0.4, 0, -7) to (1.4, 3, -6). */
  glColor3f(0.75f, 0.65f, 0.5f);
  glBegin(GL_QUADS);
  glVertex3f(0.4f, 0.0f, -6.0f);
  glVertex3f(1.4f, 0.0f, -6.0f);
  glVertex3f(1.4f, 3.0f, -6.0f);
  glVertex3f(0.4f, 3.0f, -6.0f);
  glColor3f(0.55f, 0.45f, 0.35f);
  glVertex3f(0.4f, 0.0f, -7.0f);
  glVertex3f(0.4f, 0.0f, -6.0f);
  glVertex3f(0.4f, 3.0f, -6.0f);
  glVertex3f(0.4f, 3.0f, -7.0f);
  glEnd();
}

static void sprites(void)
{
  glDisable(GL_FOG);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  /* From 3 to 12 units away; the fourth lies behind the pillar, the fifth beside it. */
  static const float places[5][3] = {
      {-2.2f, 0.6f, -3.0f}, {-1.0f, 0.9f, -4.5f}, {-0.3f, 1.0f, -6.5f}, {1.0f, 1.2f, -8.0f},
      {2.4f, 1.4f, -12.0f}};
  for (int i = 0; i < 5; ++i) {
    glRasterPos3fv(places[i]);
    glDrawPixels(SPRITE, SPRITE, GL_RGBA, GL_UNSIGNED_BYTE, sprite);
  }
  glDisable(GL_ALPHA_TEST);
  glEnable(GL_FOG);
}

static void litLabels(void)
{
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat light[4] = {-1.0f, 0.3f, 0.4f, 0.0f};
  const GLfloat red[4] = {0.9f, 0.1f, 0.1f, 1.0f};
  const GLfloat ambient[4] = {0.1f, 0.1f, 0.3f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glColor3f(1.0f, 1.0f, 1.0f); /* not used: lighting is on */
  glDisable(GL_FOG);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 5; ++i) {
    /* Normals turning from the light (left) to away from it. */
    const float a = -1.0f + 0.5f * i;
    glNormal3f(-1.0f + 0.5f * i, 0.0f, 1.0f - (a < 0 ? -a : a) * 0.5f);
    glRasterPos3f(-3.0f + 1.1f * i, 2.4f, -4.0f);
    glBitmap(16, 12, 0.0f, 0.0f, 18.0f, 0.0f, arrow);
    glBitmap(16, 12, 0.0f, 0.0f, 0.0f, 0.0f, arrow);
  }
  glDisable(GL_LIGHTING);
  glEnable(GL_FOG);
}

static void texturedPixels(void)
{
  static const GLubyte texels[2][2][4] = {{{255, 255, 255, 255}, {255, 80, 80, 255}},
                                          {{80, 255, 80, 255}, {90, 90, 255, 255}}};
  GLuint texture;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glDisable(GL_FOG);
  glDisable(GL_DEPTH_TEST);

  /* In window coordinates from here on. */
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  static const float coords[4][2] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}};
  for (int i = 0; i < 4; ++i) {
    glTexCoord2fv(coords[i]);
    glRasterPos2i(12 + 32 * i, HEIGHT - 36);
    glDrawPixels(SPRITE, SPRITE, GL_RGBA, GL_UNSIGNED_BYTE, sprite);
  }
  /* A bitmap's bits textured by the raster texture coordinates: green. */
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexCoord2f(0.25f, 0.75f);
  glRasterPos2i(160, HEIGHT - 30);
  glBitmap(16, 12, 0.0f, 0.0f, 0.0f, 0.0f, arrow);

  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &texture);
}

static void draw(void)
{
  const GLfloat fogColor[4] = {0.6f, 0.65f, 0.75f, 1.0f};
  glClearColor(fogColor[0], fogColor[1], fogColor[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)WIDTH / HEIGHT, 0.5, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.6, 1.5, 0.0, 1.0, -6.0, 0.0, 1.0, 0.0);

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 14.0f);
  glFogfv(GL_FOG_COLOR, fogColor);

  makeSprite();
  scene();
  sprites();
  litLabels();
  texturedPixels();
  glDisable(GL_FOG);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
