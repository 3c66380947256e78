// Draws are queued and rasterized later on GLASS_THREADS threads (primitive/draw_pipeline.h), so
// every GL state a queued draw reads must be the state at the time of the draw, not the state
// when the queue is finished. This test changes such state between many draws of one frame (and
// inside glBegin/glEnd where GL allows it) and renders the same frame in two ways:
//   - the reference: glFinish after every draw, so nothing is ever queued across a state change,
//     which is what drawing each primitive at once gives;
//   - queued: no glFinish, draws pile up across the state changes.
// Both with GLASS_THREADS=1 and 4. Every buffer read back (colour, depth and stencil of two
// contexts, and pixels read in the middle of the frame) must have the same bytes in all four.
// A snapshot that is missing or taken too late shows as a difference between queued and
// reference.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 200, kHeight = 150;  // partial tiles on the right and at the top
constexpr int kOtherWidth = 96, kOtherHeight = 80;

const GLenum kCompares[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                            GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

class FrameRecorder {
 public:
  explicit FrameRecorder(bool finishEachDraw) : finishEachDraw_(finishEachDraw) {}

  // After each draw: the reference waits for it.
  void drawn() const {
    if (finishEachDraw_) glFinish();
  }

  // Appends what glReadPixels returns for a region of the current context.
  void read(int x, int y, int w, int h, GLenum format, GLenum type, int bytesPerPixel) {
    std::vector<uint8_t> pixels(static_cast<size_t>(w) * h * bytesPerPixel);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, w, h, format, type, pixels.data());
    bytes.insert(bytes.end(), pixels.begin(), pixels.end());
  }
  void readAll(int w, int h) {
    read(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    read(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 4);
    read(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 1);
  }

  std::vector<uint8_t> bytes;

 private:
  bool finishEachDraw_;
};

void pixelProjection(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// A smooth-shaded quad from (x0, y0) to (x1, y1) at depth z, with texture coordinates 0..1.
void quad(float x0, float y0, float x1, float y1, float z, float shade) {
  glBegin(GL_QUADS);
  glColor4f(shade, 1.0f - shade, 0.5f, 0.25f);
  glTexCoord2f(0, 0);
  glVertex3f(x0, y0, z);
  glColor4f(1.0f, shade, 0.2f, 0.75f);
  glTexCoord2f(1, 0);
  glVertex3f(x1, y0, z);
  glColor4f(0.3f, 0.6f, shade, 1.0f);
  glTexCoord2f(1, 1);
  glVertex3f(x1, y1, -z);
  glColor4f(shade * 0.5f, 0.9f, 1.0f - shade, 0.5f);
  glTexCoord2f(0, 1);
  glVertex3f(x0, y1, -z);
  glEnd();
}

// The i-th of a family of overlapping quads spread over the whole window.
void overlappingQuad(int i) {
  const float x = static_cast<float>((i * 37) % 120), y = static_cast<float>((i * 23) % 90);
  quad(x, y, x + 80.0f, y + 60.0f, -0.8f + 0.13f * static_cast<float>(i % 12), (i % 7) / 6.0f);
}

void fillTexture(int variant) {
  uint8_t texels[8 * 8 * 4];
  for (int t = 0; t < 8; ++t)
    for (int s = 0; s < 8; ++s) {
      uint8_t* p = texels + (t * 8 + s) * 4;
      p[0] = static_cast<uint8_t>((s * 32 + variant * 50) & 255);
      p[1] = static_cast<uint8_t>((t * 32 + variant * 90) & 255);
      p[2] = static_cast<uint8_t>(((s ^ t) & 1) ? 255 - variant * 20 : variant * 20);
      p[3] = static_cast<uint8_t>(128 + variant * 10);
    }
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

void depthAndStencil(const FrameRecorder& frame) {
  glEnable(GL_DEPTH_TEST);
  for (int i = 0; i < 16; ++i) {
    glDepthFunc(kCompares[(i * 3) % 8]);
    glDepthMask(i % 3 != 0);
    overlappingQuad(i);
    frame.drawn();
  }
  glEnable(GL_STENCIL_TEST);
  const GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT};
  for (int i = 0; i < 16; ++i) {
    glStencilFunc(kCompares[(i * 5 + 3) % 8], (i * 37) & 255, i % 2 ? 0xFF : 0x3C);
    glStencilOp(ops[i % 6], ops[(i + 2) % 6], ops[(i + 4) % 6]);
    glStencilMask(i % 4 ? 0xFF : 0x0F);
    glDepthFunc(kCompares[(i * 5) % 8]);
    overlappingQuad(i + 3);
    frame.drawn();
  }
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

void blendingAndMasks(const FrameRecorder& frame) {
  const GLenum factors[] = {GL_ZERO, GL_ONE, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR,
                            GL_ONE_MINUS_DST_COLOR, GL_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE};
  const GLenum equations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
  glEnable(GL_BLEND);
  for (int i = 0; i < 16; ++i) {
    glBlendFunc(factors[i % 8], factors[(i * 3 + 1) % 7]);
    glBlendEquation(equations[i % 5]);
    glBlendColor(0.1f * (i % 10), 0.5f, 1.0f - 0.05f * i, 0.5f);
    overlappingQuad(i);
    frame.drawn();
  }
  glDisable(GL_BLEND);

  glEnable(GL_ALPHA_TEST);
  for (int i = 0; i < 8; ++i) {
    glAlphaFunc(kCompares[i], 0.1f * static_cast<float>(i + 1));
    overlappingQuad(i + 5);
    frame.drawn();
  }
  glDisable(GL_ALPHA_TEST);

  const GLenum logicOps[] = {GL_XOR, GL_AND, GL_OR_REVERSE, GL_COPY_INVERTED, GL_NAND, GL_EQUIV};
  glEnable(GL_COLOR_LOGIC_OP);
  for (int i = 0; i < 12; ++i) {
    glLogicOp(logicOps[i % 6]);
    overlappingQuad(i + 2);
    frame.drawn();
  }
  glDisable(GL_COLOR_LOGIC_OP);

  for (int i = 0; i < 16; ++i) {
    glColorMask(i & 1, (i >> 1) & 1, (i >> 2) & 1, (i >> 3) & 1);
    glDisable(i % 2 ? GL_DITHER : GL_CULL_FACE);
    overlappingQuad(i + 4);
    frame.drawn();
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DITHER);

  glEnable(GL_SCISSOR_TEST);
  for (int i = 0; i < 10; ++i) {
    glScissor(i * 13, i * 9, 70 + i * 5, 40 + i * 3);
    overlappingQuad(i + 1);
    frame.drawn();
  }
  glDisable(GL_SCISSOR_TEST);

  // glDrawBuffer: whatever it does to drawing, queued draws must see the value of their time.
  for (int i = 0; i < 4; ++i) {
    glDrawBuffer(i % 2 ? GL_NONE : GL_FRONT);
    overlappingQuad(i + 6);
    frame.drawn();
  }
  glDrawBuffer(GL_FRONT);
}

void stipplesLinesPoints(const FrameRecorder& frame) {
  glEnable(GL_POLYGON_STIPPLE);
  for (int i = 0; i < 6; ++i) {
    GLubyte pattern[128];
    for (int k = 0; k < 128; ++k) pattern[k] = static_cast<GLubyte>((k * (i + 3) * 29) ^ (0x55 << (i % 2)));
    glPolygonStipple(pattern);
    overlappingQuad(i + 7);
    frame.drawn();
  }
  glDisable(GL_POLYGON_STIPPLE);

  glEnable(GL_LINE_STIPPLE);
  for (int i = 0; i < 8; ++i) {
    glLineStipple(1 + i % 3, static_cast<GLushort>(0xF0F0 ^ (i * 0x1357)));
    glLineWidth(1.0f + static_cast<float>(i % 3));
    glShadeModel(i % 2 ? GL_FLAT : GL_SMOOTH);
    glBegin(GL_LINE_STRIP);
    for (int k = 0; k < 12; ++k) {
      glColor3f(k / 11.0f, 1.0f - i / 7.0f, 0.5f);
      glVertex2f(5.0f + k * 16.0f, 10.0f + ((k * 7 + i * 11) % 13) * 10.0f);
    }
    glEnd();
    frame.drawn();
  }
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glShadeModel(GL_SMOOTH);
  for (int i = 0; i < 6; ++i) {
    glPointSize(1.0f + static_cast<float>(i));
    if (i % 2) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
    glBegin(GL_POINTS);
    for (int k = 0; k < 10; ++k) {
      glColor3f(i / 5.0f, k / 9.0f, 0.3f);
      glVertex2f(8.0f + k * 19.0f, 12.0f + i * 22.0f);
    }
    glEnd();
    frame.drawn();
  }
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1.0f);
}

void texturing(const FrameRecorder& frame, GLuint textures[2]) {
  glEnable(GL_TEXTURE_2D);
  const GLenum envModes[] = {GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND};
  for (int i = 0; i < 12; ++i) {
    glBindTexture(GL_TEXTURE_2D, textures[i % 3 == 2 ? 1 : 0]);
    // Now and then the image is specified anew, at another size (new texel storage).
    if (i % 4 == 3) {
      const int size = i % 8 == 3 ? 16 : 8;
      std::vector<uint8_t> grey(static_cast<size_t>(size) * size * 4, static_cast<uint8_t>(40 + 9 * i));
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey.data());
    }
    fillTexture(i);  // changes the texture object in place
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, i % 2 ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, i % 4 < 2 ? GL_REPEAT : GL_CLAMP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, envModes[i % 4]);
    const float envColor[4] = {0.2f * (i % 5), 0.7f, 0.1f, 1.0f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
    overlappingQuad(i + 8);
    frame.drawn();
  }
  // A texture copied from the framebuffer must hold the draws before the copy.
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 60, 40, 8, 8);
  overlappingQuad(3);
  frame.drawn();
  glDisable(GL_TEXTURE_2D);
}

void fog(const FrameRecorder& frame) {
  glEnable(GL_FOG);
  const GLenum modes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
  for (int i = 0; i < 9; ++i) {
    glFogi(GL_FOG_MODE, static_cast<GLint>(modes[i % 3]));
    glFogf(GL_FOG_DENSITY, 0.3f + 0.2f * i);
    glFogf(GL_FOG_START, -1.0f + 0.1f * i);
    glFogf(GL_FOG_END, 1.0f);
    const float color[4] = {1.0f - 0.1f * i, 0.1f * i, 0.5f, 1.0f};
    glFogfv(GL_FOG_COLOR, color);
    overlappingQuad(i + 9);
    frame.drawn();
  }
  glDisable(GL_FOG);
}

void perFragmentLighting(const FrameRecorder& frame) {
  glShadeModel(GL_PHONG_WIN);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  for (int i = 0; i < 8; ++i) {
    const float position[4] = {40.0f + 15.0f * i, 70.0f, 60.0f, 1.0f};
    const float diffuse[4] = {1.0f, 0.2f * (i % 5), 0.6f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    const float material[4] = {0.3f + 0.1f * i, 0.8f, 0.4f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, material);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 5.0f + 10.0f * i);
    const float x = static_cast<float>(i * 17), y = static_cast<float>((i * 29) % 70);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(x, y, 0.2f);
    glVertex3f(x + 70.0f, y, 0.2f);
    glVertex3f(x + 35.0f, y + 70.0f, 0.2f);
    // glMaterial between glBegin and glEnd: the triangles before it keep the old material.
    const float specular[4] = {0.9f, 0.9f * (i % 2), 0.5f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glVertex3f(x + 10.0f, y + 10.0f, 0.3f);
    glVertex3f(x + 80.0f, y + 30.0f, 0.3f);
    glVertex3f(x + 20.0f, y + 75.0f, 0.3f);
    glEnd();
    frame.drawn();
  }
  // Colour material: glColor between glBegin and glEnd changes the material. Enough tiny
  // triangles that the rasterizer starts on them before glEnd.
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glBegin(GL_TRIANGLE_STRIP);
  glNormal3f(0.0f, 0.3f, 1.0f);
  for (int k = 0; k < 90000; ++k) {
    const float x = static_cast<float>((k / 2) % 190) + 0.5f * (k % 2);
    const float y = 5.0f + static_cast<float>((k / 380) % 140) + (k % 2);
    glColor3f((k % 97) / 96.0f, (k % 31) / 30.0f, 0.5f);
    glVertex3f(x, y, 0.5f);
  }
  glEnd();
  frame.drawn();
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_SMOOTH);
}

void viewportDepthRangeOffset(const FrameRecorder& frame) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  for (int i = 0; i < 8; ++i) {
    glViewport(i * 9 - 20, i * 5 - 10, kWidth - i * 6, kHeight + i * 4);
    glDepthRange(0.1 * (i % 4), 1.0 - 0.05 * i);
    glPolygonOffset(static_cast<float>(i % 3) - 1.0f, static_cast<float>(i * 4) - 10.0f);
    overlappingQuad(i + 11);
    frame.drawn();
  }
  glViewport(0, 0, kWidth, kHeight);
  glDepthRange(0.0, 1.0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
}

void framebufferCommands(const FrameRecorder& frame, FrameRecorder& out) {
  // Clearing a scissored part of the window, with other clear values each time.
  glEnable(GL_SCISSOR_TEST);
  for (int i = 0; i < 4; ++i) {
    glScissor(20 * i, 10 * i, 60, 50);
    glClearColor(0.25f * i, 0.1f, 1.0f - 0.25f * i, 1.0f);
    glClearDepth(0.25 * i);
    glClearStencil(i * 60);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    overlappingQuad(i + 13);
    frame.drawn();
  }
  glDisable(GL_SCISSOR_TEST);

  // The accumulation buffer takes the draws before it.
  glAccum(GL_LOAD, 0.5f);
  overlappingQuad(2);
  frame.drawn();
  glAccum(GL_ACCUM, 0.5f);
  overlappingQuad(9);
  frame.drawn();
  glAccum(GL_RETURN, 1.0f);

  // Pixel rectangles read and write the framebuffer between draws.
  uint8_t image[16 * 12 * 4];
  for (int k = 0; k < 16 * 12 * 4; ++k) image[k] = static_cast<uint8_t>(k * 7);
  glRasterPos2i(30, 40);
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, image);
  overlappingQuad(5);
  frame.drawn();
  glRasterPos2i(120, 90);
  glCopyPixels(10, 10, 50, 40, GL_COLOR);
  overlappingQuad(6);
  frame.drawn();
  // Rows of 4 bytes: the default GL_UNPACK_ALIGNMENT of 4 pads each 1-byte row (spec 3.6.4).
  const GLubyte bitmap[8 * 4] = {0xFF, 0, 0, 0, 0x81, 0, 0, 0, 0xBD, 0, 0, 0, 0xA5, 0, 0, 0,
                                 0xA5, 0, 0, 0, 0xBD, 0, 0, 0, 0x81, 0, 0, 0, 0xFF, 0, 0, 0};
  glRasterPos2i(70, 70);
  glBitmap(8, 8, 0, 0, 0, 0, bitmap);
  overlappingQuad(8);
  frame.drawn();

  // Pixels read in the middle of the frame hold the draws before the read.
  out.read(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, 4);
  overlappingQuad(10);
  frame.drawn();
}

// One frame of everything above in context `a`, with draws in a second context `b` in between
// and a third context destroyed with its draws still queued. Returns every byte read back.
std::vector<uint8_t> renderFrame(int threads, bool finishEachDraw) {
  const std::string count = std::to_string(threads);
  setenv("GLASS_THREADS", count.c_str(), 1);
  GlassContext* a = glassCreateContext(kWidth, kHeight);
  GlassContext* b = glassCreateContext(kOtherWidth, kOtherHeight);
  GlassContext* doomed = glassCreateContext(kWidth, kHeight);
  unsetenv("GLASS_THREADS");
  REQUIRE(a != nullptr);
  REQUIRE(b != nullptr);
  REQUIRE(doomed != nullptr);
  FrameRecorder frame(finishEachDraw);

  glassMakeCurrent(b);
  pixelProjection(kOtherWidth, kOtherHeight);
  glClearColor(0.0f, 0.3f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  glassMakeCurrent(a);
  pixelProjection(kWidth, kHeight);
  GLuint textures[2];
  glGenTextures(2, textures);
  for (GLuint texture : textures) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fillTexture(static_cast<int>(texture));
  }
  glClearColor(0.1f, 0.2f, 0.3f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  depthAndStencil(frame);
  // Another context in between: its draws and state are its own.
  glassMakeCurrent(b);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (int i = 0; i < 6; ++i) {
    quad(i * 10.0f, i * 8.0f, i * 10.0f + 40.0f, i * 8.0f + 30.0f, 0.0f, i / 5.0f);
    frame.drawn();
  }
  glassMakeCurrent(doomed);
  pixelProjection(kWidth, kHeight);
  for (int i = 0; i < 20; ++i) {
    overlappingQuad(i);
    frame.drawn();
  }
  glassMakeCurrent(a);
  blendingAndMasks(frame);
  glassDestroyContext(doomed);  // with its draws queued (unless the reference finished them)
  stipplesLinesPoints(frame);
  glassMakeCurrent(b);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  for (int i = 0; i < 6; ++i) {
    quad(80.0f - i * 10.0f, i * 8.0f, 90.0f - i * 8.0f, i * 8.0f + 30.0f, 0.0f, i / 5.0f);
    frame.drawn();
  }
  glassMakeCurrent(a);
  texturing(frame, textures);
  fog(frame);
  perFragmentLighting(frame);
  viewportDepthRangeOffset(frame);
  framebufferCommands(frame, frame);

  frame.readAll(kWidth, kHeight);
  glassMakeCurrent(b);
  frame.readAll(kOtherWidth, kOtherHeight);
  // glassGetColorBuffer must hold every draw too, without a GL call before it.
  overlappingQuad(4);
  const unsigned char* colors = glassGetColorBuffer(b);
  frame.bytes.insert(frame.bytes.end(), colors, colors + kOtherWidth * kOtherHeight * 4);

  glassMakeCurrent(nullptr);
  glassDestroyContext(a);
  glassDestroyContext(b);
  return frame.bytes;
}

size_t distinctColors(const std::vector<uint8_t>& bytes) {
  std::set<uint32_t> colors;
  for (size_t i = 0; i + 4 <= static_cast<size_t>(kWidth) * kHeight * 4; i += 4)
    colors.insert(uint32_t{bytes[i]} | uint32_t{bytes[i + 1]} << 8 | uint32_t{bytes[i + 2]} << 16);
  return colors.size();
}

size_t differingBytes(const std::vector<uint8_t>& x, const std::vector<uint8_t>& y) {
  if (x.size() != y.size()) return std::max(x.size(), y.size());
  size_t n = 0;
  for (size_t i = 0; i < x.size(); ++i) n += x[i] != y[i];
  return n;
}

}  // namespace

TEST_CASE("queued draws: state changed between and inside draws reaches only later draws") {
  const std::vector<uint8_t> reference = renderFrame(1, true);
  // The frame draws many different things (a blank or one-colour picture would prove nothing).
  CHECK(distinctColors(reference) > 500);

  CHECK(differingBytes(renderFrame(1, false), reference) == 0);
  CHECK(differingBytes(renderFrame(4, false), reference) == 0);
  CHECK(differingBytes(renderFrame(4, true), reference) == 0);
}
