// Texture objects shared with the sharelist context (pipeline/src/texture/texture_names.h):
// names, contents and deletion seen by every context of the share group and by no other, and
// contexts sampling one shared texture on several threads at once.
#include <doctest/doctest.h>

#include <vector>

#include "osmesa_test_scene.h"

using osmesa_test::createContext;

namespace {

// A 2x2 texture of one colour on the texture bound to GL_TEXTURE_2D.
void loadSolidTexture(uint8_t r, uint8_t g, uint8_t b) {
  const uint8_t texels[16] = {r, g, b, 255, r, g, b, 255, r, g, b, 255, r, g, b, 255};
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

// A square from -extent to extent with texture coordinates 0 to repeat.
void texturedSquare(float extent, float repeat) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(-extent, -extent);
  glTexCoord2f(repeat, 0), glVertex2f(extent, -extent);
  glTexCoord2f(repeat, repeat), glVertex2f(extent, extent);
  glTexCoord2f(0, repeat), glVertex2f(-extent, extent);
  glEnd();
}

// Fills the viewport with texture `name` (GL_REPLACE) and returns the centre pixel's RGB.
std::vector<uint8_t> drawTextured(GLuint name, const std::vector<uint8_t>& buffer, int size) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindTexture(GL_TEXTURE_2D, name);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  texturedSquare(1.0f, 1.0f);
  glFinish();
  const size_t centre = (static_cast<size_t>(size / 2) * size + size / 2) * 4;
  return {buffer[centre], buffer[centre + 1], buffer[centre + 2]};
}

}  // namespace

TEST_CASE("texture objects are shared with the sharelist context, not with others") {
  constexpr int kSize = 8;
  std::vector<uint8_t> a(kSize * kSize * 4), b(kSize * kSize * 4), c(kSize * kSize * 4);
  OSMesaContext first = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(first, a.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  GLuint red = 0;
  glGenTextures(1, &red);
  glBindTexture(GL_TEXTURE_2D, red);
  loadSolidTexture(255, 0, 0);

  OSMesaContext sharing = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, first);
  OSMesaContext separate = createContext(OSMESA_RGBA);
  REQUIRE(sharing != nullptr);

  // The sharing context sees the name and the image.
  REQUIRE(OSMesaMakeCurrent(sharing, b.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(glIsTexture(red));
  CHECK(drawTextured(red, b, kSize) == std::vector<uint8_t>{255, 0, 0});
  // Names generated here are not handed out again there, and its textures are the first's.
  GLuint green = 0;
  glGenTextures(1, &green);
  CHECK(green != red);
  glBindTexture(GL_TEXTURE_2D, green);
  loadSolidTexture(0, 255, 0);

  // Another context has neither: binding the same name there makes a texture of its own.
  REQUIRE(OSMesaMakeCurrent(separate, c.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(!glIsTexture(red));
  CHECK(!glIsTexture(green));
  CHECK(drawTextured(red, c, kSize) == std::vector<uint8_t>{255, 255, 255});  // incomplete: unit off

  REQUIRE(OSMesaMakeCurrent(first, a.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(glIsTexture(green));
  CHECK(drawTextured(green, a, kSize) == std::vector<uint8_t>{0, 255, 0});
  // A new image for a shared texture is seen by the other context at its next draw.
  glBindTexture(GL_TEXTURE_2D, red);
  loadSolidTexture(0, 0, 255);
  REQUIRE(OSMesaMakeCurrent(sharing, b.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(drawTextured(red, b, kSize) == std::vector<uint8_t>{0, 0, 255});

  // Deleting in one context frees the name for all; a context that has it bound keeps drawing
  // with it until it binds another (the binding is not pulled from under it).
  glBindTexture(GL_TEXTURE_2D, green);
  REQUIRE(OSMesaMakeCurrent(first, a.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  glDeleteTextures(1, &green);
  CHECK(!glIsTexture(green));
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  CHECK(bound == static_cast<GLint>(red));  // the first context had red bound, not green
  REQUIRE(OSMesaMakeCurrent(sharing, b.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(!glIsTexture(green));
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  CHECK(bound == static_cast<GLint>(green));
  glClear(GL_COLOR_BUFFER_BIT);
  texturedSquare(1.0f, 1.0f);
  glFinish();
  CHECK(b[(4 * kSize + 4) * 4 + 1] == 255);  // still green
  CHECK(glGetError() == GL_NO_ERROR);

  // The textures outlive the context that made them.
  OSMesaDestroyContext(first);
  CHECK(glIsTexture(red));
  CHECK(drawTextured(red, b, kSize) == std::vector<uint8_t>{0, 0, 255});
  OSMesaDestroyContext(sharing);
  OSMesaDestroyContext(separate);
}

TEST_CASE("8 threads sampling one shared texture at once give the serial bytes") {
  constexpr int kThreads = 8, kSize = 64;
  std::vector<uint8_t> setupBuffer(kSize * kSize * 4);
  OSMesaContext owner = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(owner, setupBuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  GLuint checker = 0;
  glGenTextures(1, &checker);
  glBindTexture(GL_TEXTURE_2D, checker);
  std::vector<uint8_t> texels;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const uint8_t v = ((x / 4 + y / 4) % 2) ? 230 : 40;
      texels.insert(texels.end(), {v, static_cast<uint8_t>(x * 16), static_cast<uint8_t>(y * 16), 255});
    }
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glFinish();
  REQUIRE(OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0));

  // Each thread draws the texture rotated by its own angle.
  auto draw = [&](int variant) {
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(11.0f * static_cast<float>(variant), 0, 0, 1);
    glBindTexture(GL_TEXTURE_2D, checker);
    glEnable(GL_TEXTURE_2D);
    texturedSquare(0.8f, 3.0f);
    glFinish();
  };
  std::vector<std::vector<uint8_t>> serial(kThreads, std::vector<uint8_t>(kSize * kSize * 4));
  for (int i = 0; i < kThreads; ++i) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, owner);
    REQUIRE(OSMesaMakeCurrent(ctx, serial[i].data(), GL_UNSIGNED_BYTE, kSize, kSize));
    draw(i);
    OSMesaDestroyContext(ctx);
  }
  std::vector<int> failures;
  const auto parallel = osmesa_test::renderOnThreads(
      kThreads, kSize, kSize, [&] { return OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, owner); },
      [&](int i) {
        for (int frame = 0; frame < 3; ++frame) draw(i);
      },
      failures);
  for (int i = 0; i < kThreads; ++i) {
    CAPTURE(i);
    CHECK(failures[i] == 0);
    CHECK(parallel[i] == serial[i]);
  }
  CHECK(serial[0] != serial[1]);
  OSMesaDestroyContext(owner);
}
