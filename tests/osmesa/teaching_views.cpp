// GLASS_VIEW in an OSMesa program: the caller's buffer receives the view's picture, laid out as
// the buffer's format, type and OSMESA_Y_UP say, while glReadPixels still reads the program's
// colours (docs/teaching.md).
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdlib>
#include <vector>

#include "osmesa_test_scene.h"

namespace {

constexpr int kWidth = 16, kHeight = 8;

// GLASS_VIEW for the contexts created while the object lives.
class ScopedView {
 public:
  explicit ScopedView(const char* name) { setenv("GLASS_VIEW", name, 1); }
  ~ScopedView() { unsetenv("GLASS_VIEW"); }
  ScopedView(const ScopedView&) = delete;
  ScopedView& operator=(const ScopedView&) = delete;
};

// Green quad over the bottom half of the window, with the normal (1, 0, 0): the normals view
// shows 255 (n + 1) / 2 = (255, 128, 128) there and black above.
void drawBottomHalf() {
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  glNormal3f(1.0f, 0.0f, 0.0f);
  glRectf(-1.0f, -1.0f, 1.0f, 0.0f);
  glFinish();
}

}  // namespace

TEST_CASE("GLASS_VIEW=normals fills an OSMesa BGRA buffer with the view, rows as OSMESA_Y_UP says") {
  ScopedView view("normals");
  OSMesaContext ctx = osmesa_test::createContext(OSMESA_BGRA);
  std::vector<unsigned char> buffer(kWidth * kHeight * 4, 0xA5);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
  drawBottomHalf();
  auto at = [&](int x, int row) { return &buffer[(static_cast<size_t>(row) * kWidth + x) * 4]; };
  // Y_UP (the default): row 0 is the bottom row, drawn.
  for (int x = 0; x < kWidth; ++x) {
    const unsigned char* bottom = at(x, 0);
    CHECK(bottom[0] == 128);  // B
    CHECK(bottom[1] == 128);  // G
    CHECK(bottom[2] == 255);  // R
    CHECK(bottom[3] == 255);
    const unsigned char* top = at(x, kHeight - 1);
    CHECK(top[0] == 0);
    CHECK(top[1] == 0);
    CHECK(top[2] == 0);
  }
  // The program's colour buffer is its own: green below, the clear colour blue above.
  unsigned char read[4] = {};
  glReadPixels(3, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
  CHECK(read[0] == 0);
  CHECK(read[1] == 255);
  CHECK(read[2] == 0);
  glReadPixels(3, kHeight - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
  CHECK(read[2] == 255);

  // OSMESA_Y_UP 0: the buffer's first row is the top one, so the drawn half is its last rows.
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  drawBottomHalf();
  CHECK(at(5, 0)[2] == 0);
  CHECK(at(5, kHeight - 1)[2] == 255);
  CHECK(at(5, kHeight - 1)[0] == 128);

  // OSMesaGetColorBuffer hands out the same picture.
  GLint width = 0, height = 0, format = 0;
  void* pixels = nullptr;
  REQUIRE(OSMesaGetColorBuffer(ctx, &width, &height, &format, &pixels));
  CHECK(pixels == buffer.data());
  CHECK(static_cast<unsigned char*>(pixels)[(static_cast<size_t>(kHeight - 1) * kWidth) * 4 + 2] == 255);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("GLASS_VIEW=depth fills an OSMesa float RGB buffer with the depth picture") {
  ScopedView view("depth");
  OSMesaContext ctx = osmesa_test::createContext(OSMESA_RGB);
  std::vector<float> buffer(kWidth * kHeight * 3, -1.0f);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_FLOAT, kWidth, kHeight));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Two depths: the left half nearer (black), the right half farther (white).
  glRectf(-1.0f, -1.0f, 0.0f, 1.0f);
  glTranslatef(0.0f, 0.0f, 0.5f);  // NDC z 0.5 against 0: farther
  glRectf(0.0f, -1.0f, 1.0f, 1.0f);
  glFinish();
  for (int row = 0; row < kHeight; ++row) {
    for (int x = 0; x < kWidth; ++x) {
      const float* p = &buffer[(static_cast<size_t>(row) * kWidth + x) * 3];
      const float expected = x < kWidth / 2 ? 0.0f : 1.0f;
      CHECK(p[0] == expected);
      CHECK(p[1] == expected);
      CHECK(p[2] == expected);
    }
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}
