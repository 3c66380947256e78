// Shared helpers of the pipeline unit tests: a context made current for one test, pixel reads,
// a pixel-exact 2D projection.
#pragma once

#include <GL/gl.h>
#include <glass/context.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace glass::test {

// A context of the given size, current for the lifetime of the object.
class ScopedContext {
 public:
  explicit ScopedContext(int width = 64, int height = 64)
      : ctx_(glassCreateContext(width, height)), width_(width), height_(height) {
    glassMakeCurrent(ctx_);
  }
  ~ScopedContext() { glassDestroyContext(ctx_); }
  ScopedContext(const ScopedContext&) = delete;
  ScopedContext& operator=(const ScopedContext&) = delete;

  GlassContext* get() const { return ctx_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GlassContext* ctx_;
  int width_, height_;
};

struct Rgba {
  uint8_t r, g, b, a;
  bool operator==(const Rgba&) const = default;
};

inline Rgba pixelAt(int x, int y) {
  Rgba p{0, 0, 0, 0};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &p);
  return p;
}

inline uint8_t stencilAt(int x, int y) {
  uint8_t s = 0;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  return s;
}

// The whole colour buffer, RGBA, bottom row first.
inline std::vector<uint8_t> readFramebuffer(int width, int height) {
  std::vector<uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

// Object coordinates = window coordinates: (0, 0) is the bottom-left corner of pixel (0, 0).
inline void pixelProjection(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// An axis-aligned rectangle in normalized device coordinates (identity matrices) at depth z,
// texture coordinates 0 to 1 across it.
inline void rectangleNdc(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(x0, y0, z);
  glTexCoord2f(1.0f, 0.0f);
  glVertex3f(x1, y0, z);
  glTexCoord2f(1.0f, 1.0f);
  glVertex3f(x1, y1, z);
  glTexCoord2f(0.0f, 1.0f);
  glVertex3f(x0, y1, z);
  glEnd();
}

// Reads and clears the GL error flag.
inline GLenum takeError() { return glGetError(); }

// An environment variable set for the lifetime of the object (the teaching tools read theirs
// when a context is created), unset afterwards.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) { setenv(name, value, 1); }
  ~ScopedEnvironment() { unsetenv(name_); }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
};

}  // namespace glass::test
