#include "osmesa_test_scene.h"

#include <GL/glu.h>
#include <doctest/doctest.h>

#include <atomic>
#include <thread>

namespace osmesa_test {

void drawScene(int variant) {
  const float shade = 0.1f * static_cast<float>(variant % 8);
  GLint size[2];
  OSMesaGetIntegerv(OSMESA_WIDTH, &size[0]);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &size[1]);
  glViewport(0, 0, size[0], size[1]);

  glClearColor(0.1f + shade, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, static_cast<double>(size[0]) / size[1], 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  // A checkerboard texture on the floor.
  uint8_t checker[8 * 8 * 3];  // one per call: threads draw their own variants at once
  for (int i = 0; i < 64; ++i) {
    const uint8_t v = ((i / 8 + i % 8) % 2) ? 230 : 40;
    checker[i * 3] = v;
    checker[i * 3 + 1] = static_cast<uint8_t>(v / 2 + variant * 10);
    checker[i * 3 + 2] = v;
  }
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, checker);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-3.0f, -1.0f, 3.0f);
  glTexCoord2f(4.0f, 0.0f); glVertex3f(3.0f, -1.0f, 3.0f);
  glTexCoord2f(4.0f, 4.0f); glVertex3f(3.0f, -1.0f, -3.0f);
  glTexCoord2f(0.0f, 4.0f); glVertex3f(-3.0f, -1.0f, -3.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &texture);

  // Lit spheres and a smooth triangle.
  const GLfloat light[] = {1.0f, 2.0f, 3.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  GLUquadric* quadric = gluNewQuadric();
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-1.5f + 1.5f * static_cast<float>(i), 0.0f, 0.0f);
    glRotatef(15.0f * static_cast<float>(variant), 0.0f, 1.0f, 0.0f);
    glColor3f(i == 0 ? 0.9f : 0.2f, i == 1 ? 0.9f : shade, i == 2 ? 0.9f : 0.2f);
    gluSphere(quadric, 0.6, 24, 12);
    glPopMatrix();
  }
  gluDeleteQuadric(quadric);
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.0f, 0.0f, 0.5f); glVertex3f(-2.0f, 1.0f, -1.0f);
  glColor4f(0.0f, 1.0f, 0.0f, 1.0f); glVertex3f(2.0f, 1.2f, -1.0f);
  glColor4f(0.0f, 0.0f, 1.0f, 0.25f); glVertex3f(0.0f, 2.0f, -1.0f);
  glEnd();
  glFinish();
}

OSMesaContext createContext(GLenum format) {
  OSMesaContext ctx = OSMesaCreateContextExt(format, 24, 8, 0, nullptr);
  REQUIRE(ctx != nullptr);
  return ctx;
}

std::vector<uint8_t> renderRGBA(int width, int height, int variant) {
  OSMesaContext ctx = createContext(OSMESA_RGBA);
  std::vector<uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
  REQUIRE(OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, width, height));
  drawScene(variant);
  CHECK(glGetError() == GL_NO_ERROR);
  OSMesaDestroyContext(ctx);
  return pixels;
}

std::vector<std::vector<uint8_t>> renderOnThreads(int threads, int width, int height,
                                                  const std::function<OSMesaContext()>& makeContext,
                                                  const std::function<void(int)>& draw,
                                                  std::vector<int>& failures) {
  std::vector<std::vector<uint8_t>> buffers(static_cast<size_t>(threads));
  failures.assign(static_cast<size_t>(threads), 0);
  std::atomic<int> ready{0};
  std::vector<std::thread> running;
  for (int i = 0; i < threads; ++i) {
    running.emplace_back([&, i] {
      OSMesaContext ctx = makeContext();
      buffers[i].assign(static_cast<size_t>(width) * height * 4, 0);
      const bool bound = ctx && OSMesaMakeCurrent(ctx, buffers[i].data(), GL_UNSIGNED_BYTE, width, height);
      ++ready;
      if (!bound) {
        failures[i] = 1;
        return;
      }
      // Start drawing together, so that the threads overlap.
      while (ready.load() < threads) std::this_thread::yield();
      draw(i);
      if (OSMesaGetCurrentContext() != ctx || glGetError() != GL_NO_ERROR) failures[i] = 1;
      OSMesaDestroyContext(ctx);
    });
  }
  for (std::thread& thread : running) thread.join();
  return buffers;
}

}  // namespace osmesa_test
