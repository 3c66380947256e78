// Texture images from colour indices (OpenGL 1.4 specification, section 3.8.1: the groups of
// glTexImage are processed as for glDrawPixels, section 3.6.4-3.6.5, where a colour index is
// shifted and offset and becomes RGBA through the GL_PIXEL_MAP_I_TO_R/G/B/A maps). GL_COLOR_INDEX
// data, GL_BITMAP included, is valid for glTexImage and glTexSubImage; glGetTexImage still takes
// colour formats only (section 6.1.4).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

struct Texel {
  GLubyte r, g, b, a;
  bool operator==(const Texel&) const = default;
};

std::vector<Texel> texImage2D(int width, int height) {
  std::vector<Texel> texels(static_cast<size_t>(width) * static_cast<size_t>(height));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  return texels;
}

// Maps of 4 entries: index i becomes red i/3, green 1 - i/3, blue 0, alpha 1 (every index
// beyond the last entry takes its value modulo the map size, spec 3.6.5).
void setIndexMaps() {
  const GLfloat red[4] = {0.0f, 1.0f / 3.0f, 2.0f / 3.0f, 1.0f};
  const GLfloat green[4] = {1.0f, 2.0f / 3.0f, 1.0f / 3.0f, 0.0f};
  const GLfloat blue[4] = {0, 0, 0, 0};
  const GLfloat alpha[4] = {1, 1, 1, 1};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, red);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, green);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, blue);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, alpha);
}

}  // namespace

TEST_CASE("texture colour indices: glTexImage2D maps indices through GL_PIXEL_MAP_I_TO_*") {
  ScopedContext context(8, 8);
  setIndexMaps();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte indices[4] = {0, 1, 2, 3};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  REQUIRE(glGetError() == GL_NO_ERROR);
  const std::vector<Texel> t = texImage2D(2, 2);
  CHECK(t[0] == Texel{0, 255, 0, 255});
  CHECK(t[1] == Texel{85, 170, 0, 255});
  CHECK(t[2] == Texel{170, 85, 0, 255});
  CHECK(t[3] == Texel{255, 0, 0, 255});

  // GL_INDEX_SHIFT and GL_INDEX_OFFSET come first: (i << 1) + 1 picks entries 1, 3, 1, 3.
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  REQUIRE(glGetError() == GL_NO_ERROR);
  const std::vector<Texel> s = texImage2D(2, 2);
  CHECK(s[0] == Texel{85, 170, 0, 255});
  CHECK(s[1] == Texel{255, 0, 0, 255});
  CHECK(s[2] == Texel{85, 170, 0, 255});
  CHECK(s[3] == Texel{255, 0, 0, 255});
}

TEST_CASE("texture colour indices: a GL_BITMAP image gives indices 0 and 1") {
  ScopedContext context(8, 8);
  setIndexMaps();
  // One row of 8 bits, most significant first: 1 0 1 1 0 0 0 1.
  const GLubyte bits[4] = {0xb1, 0, 0, 0};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
  REQUIRE(glGetError() == GL_NO_ERROR);
  const std::vector<Texel> t = texImage2D(8, 1);
  const Texel zero{0, 255, 0, 255}, one{85, 170, 0, 255};
  const Texel expected[8] = {one, zero, one, one, zero, zero, zero, one};
  for (int i = 0; i < 8; ++i) {
    INFO("texel " << i);
    CHECK(t[static_cast<size_t>(i)] == expected[i]);
  }
  // Bitmaps hold indices only.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_RGBA, GL_BITMAP, bits);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("texture colour indices: a display list maps the indices when it is executed") {
  ScopedContext context(8, 8);
  const GLubyte indices[2] = {1, 3};
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  glEndList();
  // Spec 5.4: the data is unpacked at compile time, the transfer state is that of execution.
  setIndexMaps();
  glCallList(1);
  REQUIRE(glGetError() == GL_NO_ERROR);
  GLubyte luminance[2] = {7, 7};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, luminance);
  CHECK(luminance[0] == 85);
  CHECK(luminance[1] == 255);
}

TEST_CASE("texture colour indices: glGetTexImage does not return indices, and stencil data is refused") {
  ScopedContext context(8, 8);
  // Two rows of two, each padded to the default unpack alignment of 4 bytes.
  const GLubyte indices[8] = {0, 1, 0, 0, 2, 3, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  REQUIRE(glGetError() == GL_NO_ERROR);
  GLubyte out[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, out);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices);
  CHECK(glGetError() == GL_INVALID_ENUM);
  // A packed type is no index type.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_SHORT_5_6_5, indices);
  CHECK(glGetError() == GL_INVALID_OPERATION);
}
