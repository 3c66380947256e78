// The fragments of glDrawPixels and glBitmap take their texture coordinates and their fog
// coordinate from the current raster position (OpenGL 1.5 sections 2.13, 3.6.5, 3.7 and 3.10):
// the coordinates glRasterPos computed (after texgen and the texture matrix), not the current
// ones at the time of drawing, and the raster distance as the fog coordinate. Mesa 22.3's gallium
// drivers do neither (they take the current texture coordinates and do not fog pixel
// rectangles), so the image tests leave these cases here.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

const GLubyte kWhite[4] = {255, 255, 255, 255};
const GLubyte kOneBit[1] = {0x80};

// A 2 x 2 texture, NEAREST: white, red (bottom row), green, blue (top row); GL_MODULATE.
void bindFourTexels() {
  static const GLubyte texels[16] = {255, 255, 255, 255, 255, 0, 0, 255,
                                     0, 255, 0, 255, 0, 0, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
}

const Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255};

}  // namespace

TEST_CASE("pixel fragments: textured with the raster position's coordinates, not the current ones") {
  ScopedContext context(16, 16);
  glass::test::pixelProjection(16, 16);
  bindFourTexels();

  // glTexCoord after glRasterPos changes the current coordinates only.
  glTexCoord2f(0.75f, 0.25f);
  glRasterPos2i(1, 1);
  glTexCoord2f(0.25f, 0.75f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kWhite);
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, kOneBit);  // at (1, 1) too: still red
  CHECK(pixelAt(1, 1) == kRed);
  glRasterPos2i(3, 1);  // now the raster position takes (0.25, 0.75)
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, kOneBit);
  CHECK(pixelAt(3, 1) == kGreen);

  // Texgen computes the raster coordinates from the raster position's object coordinates:
  // s = x / 16, so x = 12 gives s = 0.75 whatever the current s.
  const GLfloat plane[4] = {1.0f / 16.0f, 0.0f, 0.0f, 0.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glTexCoord2f(0.0f, 0.75f);
  glRasterPos2i(12, 5);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kWhite);
  CHECK(pixelAt(12, 5) == kBlue);
  glRasterPos2i(4, 5);  // s = 0.25
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, kOneBit);
  CHECK(pixelAt(4, 5) == kGreen);
  glDisable(GL_TEXTURE_GEN_S);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixel fragments: fogged by the raster distance") {
  ScopedContext context(64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, 1.0, 0.5, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogfv(GL_FOG_COLOR, black);
  glColor3f(1.0f, 1.0f, 1.0f);

  // Raster positions off the axis, so the distance shows, not |z_e|: (0, 1.4, -4.8) is 5 away,
  // f = (10 - 5) / 10 = 0.5 (|z_e| would give 0.52, 133).
  glRasterPos3f(0.0f, 1.4f, -4.8f);
  GLfloat distance = 0.0f, window[4] = {};
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &distance);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, window);
  CHECK(distance == doctest::Approx(5.0f).epsilon(1e-5));
  const int x = static_cast<int>(window[0] + 0.5f), y = static_cast<int>(window[1] + 0.5f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kWhite);
  CHECK(pixelAt(x, y) == Rgba{128, 128, 128, 255});

  // A bitmap at (-0.6, -0.8, -2.4): about 2.6 away, f = 0.74, 189.
  glRasterPos3f(-0.6f, -0.8f, -2.4f);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &distance);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, window);
  const float f = (10.0f - distance) / 10.0f;
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, kOneBit);
  const Rgba bit = pixelAt(static_cast<int>(window[0]), static_cast<int>(window[1]));
  CHECK(bit.r == static_cast<int>(f * 255.0f + 0.5f));
  CHECK(glGetError() == GL_NO_ERROR);
}
