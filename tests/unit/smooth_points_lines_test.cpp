// Antialiased points and lines (GL_POINT_SMOOTH, GL_LINE_SMOOTH), point parameters, the colour sum
// without lighting, and glDrawBuffer / glReadBuffer(GL_NONE) (drawing, reading, copying, glAccum).
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cmath>
#include <utility>
#include <vector>

#include "pipeline_test_support.h"
#include "primitive/point_parameters.h"
#include "primitive/raster_state.h"
#include "primitive/smooth_coverage.h"
#include "primitive/stipple_dashes.h"

using glass::gl::SmoothLineShape;
using glass::gl::SmoothPointShape;
using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::Rgba;
using glass::test::ScopedContext;
using glass::test::takeError;

namespace {

glass::raster::WindowVertex windowAt(float x, float y) {
  glass::raster::WindowVertex v{};
  v.x = x;
  v.y = y;
  v.invW = 1.0f;
  return v;
}

SmoothLineShape smoothLine(float x0, float y0, float x1, float y1, float width) {
  SmoothLineShape shape;
  REQUIRE(glass::gl::makeSmoothLine(windowAt(x0, y0), windowAt(x1, y1), width, 64, 0, shape));
  return shape;
}

// A white smooth primitive blended over black: the red channel is the coverage in 8 bits.
void prepareBlendedWhite() {
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor3f(1.0f, 1.0f, 1.0f);
}

// A quad over columns 0 .. right at eye z.
void depthQuad(float right, float z) {
  glBegin(GL_QUADS);
  glVertex3f(0.0f, 0.0f, z);
  glVertex3f(right, 0.0f, z);
  glVertex3f(right, 8.0f, z);
  glVertex3f(0.0f, 8.0f, z);
  glEnd();
}

}  // namespace

TEST_CASE("Smooth line coverage: a tent across, half a pixel of fall-off past each end") {
  // Width 1: h = 1, so coverage falls from 1 on the line to 0 one pixel away.
  const SmoothLineShape thin = smoothLine(10.0f, 20.5f, 30.0f, 20.5f, 1.0f);
  CHECK(thin.coverage(20.5f, 20.5f) == doctest::Approx(1.0f));
  CHECK(thin.coverage(20.5f, 21.0f) == doctest::Approx(0.5f));
  CHECK(thin.coverage(20.5f, 19.75f) == doctest::Approx(0.25f));
  CHECK(thin.coverage(20.5f, 21.5f) == doctest::Approx(0.0f));
  // At an endpoint 1/2, half a pixel beyond it 0, half a pixel inside it 1.
  CHECK(thin.coverage(10.0f, 20.5f) == doctest::Approx(0.5f));
  CHECK(thin.coverage(9.5f, 20.5f) == doctest::Approx(0.0f));
  CHECK(thin.coverage(10.5f, 20.5f) == doctest::Approx(1.0f));
  CHECK(thin.coverage(30.25f, 20.5f) == doctest::Approx(0.25f));

  // Width 3: h = 2, full over the inner 2 pixels (|b| <= 1), 0 at |b| = 2.
  const SmoothLineShape wide = smoothLine(10.0f, 10.0f, 40.0f, 40.0f, 3.0f);
  const float n = std::sqrt(0.5f);  // the unit normal (-n, n)
  CHECK(wide.coverage(25.0f - 1.0f * n, 25.0f + 1.0f * n) == doctest::Approx(1.0f));
  CHECK(wide.coverage(25.0f + 1.5f * n, 25.0f - 1.5f * n) == doctest::Approx(0.5f));
  CHECK(wide.coverage(25.0f + 2.0f * n, 25.0f - 2.0f * n) == doctest::Approx(0.0f).epsilon(1e-5));
}

TEST_CASE("Smooth line coverage: a segment shorter than a pixel is scaled by L / (L/2 + 1/2)") {
  // L = 0.5: l = 0.75; at the midpoint clamp(l, 0, 1) * L / l = L.
  const SmoothLineShape shortLine = smoothLine(5.0f, 10.5f, 5.5f, 10.5f, 1.0f);
  CHECK(shortLine.coverage(5.25f, 10.5f) == doctest::Approx(0.5f));
  // At the centre of pixel 5, 0.25 from the midpoint: (0.75 - 0.25) * 0.5 / 0.75 = 1/3, the value
  // llvmpipe draws (85 of 255).
  CHECK(shortLine.coverage(5.5f, 10.5f) == doctest::Approx(1.0f / 3.0f));
  SmoothLineShape none;
  CHECK_FALSE(glass::gl::makeSmoothLine(windowAt(3.0f, 3.0f), windowAt(3.0f, 3.0f), 1.0f, 64, 0,
                                        none));
}

TEST_CASE("Smooth line rectangle: widened by h each side and extended by half a pixel") {
  const SmoothLineShape s = smoothLine(10.0f, 20.0f, 30.0f, 20.0f, 1.0f);
  float xMin = 1e9f, xMax = -1e9f, yMin = 1e9f, yMax = -1e9f;
  for (const auto& c : s.corners) {
    xMin = std::fmin(xMin, c.x), xMax = std::fmax(xMax, c.x);
    yMin = std::fmin(yMin, c.y), yMax = std::fmax(yMax, c.y);
  }
  CHECK(xMin == 9.5f);
  CHECK(xMax == 30.5f);
  CHECK(yMin == 19.0f);
  CHECK(yMax == 21.0f);
  CHECK(smoothLine(0, 0, 10, 0, 4.0f).halfWidth == 2.5f);  // w/2 + 1/2
  CHECK(smoothLine(0, 0, 10, 0, 0.5f).halfWidth == 1.0f);  // at least 1
}

TEST_CASE("Stippled smooth lines: dashes of whole steps along the Euclidean length") {
  std::vector<std::pair<float, float>> dashes;
  auto record = [&](float t0, float t1) { dashes.emplace_back(t0, t1); };
  // 0x00FF: steps 0-7 on, 8-15 off, 16-19 on.
  CHECK(glass::gl::forEachStippleDash(20.0f, 0, 0x00FF, 1, record) == 20);
  REQUIRE(dashes.size() == 2);
  CHECK(dashes[0] == std::pair(0.0f, 0.4f));
  CHECK(dashes[1] == std::pair(0.8f, 1.0f));
  // Carried on from counter 4, factor 2, 0x00F0: steps 0-5 are counters 4-9, bits 2, 2, 3, 3, 4,
  // 4, so the dash starts at step 4 and runs to the end; the counter advances by ceil(5.5).
  dashes.clear();
  CHECK(glass::gl::forEachStippleDash(5.5f, 4, 0x00F0, 2, record) == 10);
  REQUIRE(dashes.size() == 1);
  CHECK(dashes[0].first == doctest::Approx(4.0f / 5.5f));
  CHECK(dashes[0].second == 1.0f);
  dashes.clear();
  CHECK(glass::gl::forEachStippleDash(0.0f, 3, 0xFFFF, 1, record) == 3);
  CHECK(dashes.empty());
}

TEST_CASE("Smooth points: radius 1 up to size 2, size / 2 above; discs with discarded corners") {
  CHECK(glass::gl::smoothPointRadius(1.0f, false) == 1.0f);
  CHECK(glass::gl::smoothPointRadius(2.0f, false) == 1.0f);
  CHECK(glass::gl::smoothPointRadius(5.0f, false) == 2.5f);
  CHECK(glass::gl::smoothPointRadius(1.0f, true) == 0.5f);  // attenuated: size / 2 always

  SmoothPointShape p;
  glass::gl::makeSmoothPoint(windowAt(20.0f, 20.0f), 5.0f, 64, 0, p);
  CHECK(p.coverage(20.5f, 20.5f) >= 1.0f);
  CHECK(p.coverage(24.5f, 20.5f) == 1.0f);  // the outer ring: Mesa's coverage 1
  CHECK(p.coverage(24.5f, 23.5f) < 0.0f);   // outside the disc: discarded
  CHECK(p.coverage(23.5f, 23.5f) == 1.0f);
}

TEST_CASE("GL_POINT_SMOOTH draws round points, GL_LINE_SMOOTH blends coverage into alpha") {
  ScopedContext context(32, 32);
  pixelProjection(32, 32);
  prepareBlendedWhite();
  glEnable(GL_POINT_SMOOTH);
  glPointSize(8.0f);
  glBegin(GL_POINTS);
  glVertex2f(16.0f, 16.0f);
  glEnd();
  // Radius 4 around a pixel corner: pixel centres within distance 4 are drawn.
  CHECK(pixelAt(12, 16).r == 255);  // (12.5, 16.5): distance 3.54
  CHECK(pixelAt(12, 12).r == 0);    // (12.5, 12.5): distance 4.95, a corner of the square
  CHECK(pixelAt(13, 13).r == 255);  // (13.5, 13.5): distance 3.54
  CHECK(pixelAt(18, 18).r == 255);  // (18.5, 18.5): distance 3.54
  CHECK(pixelAt(19, 12).r == 0);    // (19.5, 12.5): distance 4.95
  glDisable(GL_POINT_SMOOTH);

  prepareBlendedWhite();
  glEnable(GL_LINE_SMOOTH);
  glBegin(GL_LINES);
  glVertex2f(4.0f, 10.75f);
  glVertex2f(28.0f, 10.75f);
  glEnd();
  // Pixel centres 0.25 and 0.75 from the line: coverage 0.75 and 0.25; 1.25 and more: 0.
  CHECK(pixelAt(16, 10).r == 191);
  CHECK(pixelAt(16, 11).r == 64);
  CHECK(pixelAt(16, 9).r == 0);
  CHECK(pixelAt(16, 12).r == 0);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_BLEND);
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("Point parameters: size * sqrt(1 / (a + b d + c d^2)), clamped to min and max") {
  glass::gl::RasterState r;
  r.pointSize = 8.0f;
  CHECK_FALSE(glass::gl::pointSizeAttenuated(r));
  CHECK(glass::gl::derivedPointSize(r, 10.0f) == 8.0f);
  r.pointDistanceAttenuation[0] = 0.0f;
  r.pointDistanceAttenuation[2] = 0.25f;  // 1 / sqrt(d^2 / 4) = 2 / d
  CHECK(glass::gl::pointSizeAttenuated(r));
  CHECK(glass::gl::derivedPointSize(r, 4.0f) == doctest::Approx(4.0f));
  CHECK(glass::gl::derivedPointSize(r, 1.0f) == doctest::Approx(16.0f));
  r.pointSizeMin = 5.0f;
  r.pointSizeMax = 12.0f;
  CHECK(glass::gl::derivedPointSize(r, 4.0f) == 5.0f);
  CHECK(glass::gl::derivedPointSize(r, 1.0f) == 12.0f);
}

TEST_CASE("Point parameters change the drawn size with the eye distance") {
  ScopedContext context(64, 64);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-32.0, 32.0, -32.0, 32.0, 0.0, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat quadratic[3] = {0.0f, 0.0f, 1.0f};  // size / d
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quadratic);
  glPointSize(40.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  auto widthAt = [](int row) {
    int count = 0;
    for (int x = 0; x < 64; ++x) count += pixelAt(x, row).r == 255;
    return count;
  };
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 16.0f, -5.0f);   // d = sqrt(16^2 + 5^2) = 16.76: size 2.39 -> 2 pixels
  glVertex3f(0.0f, -16.0f, -10.0f); // d = 18.87: size 2.12 -> 2 pixels
  glVertex3f(0.0f, 0.0f, -4.0f);    // d = 4: size 10
  glEnd();
  CHECK(widthAt(32) == 10);
  CHECK(widthAt(48) == 2);
  // GL_POINT_FADE_THRESHOLD_SIZE only fades with multisampling: no change here.
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 20.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 0.0f, -8.0f);  // size 5
  glEnd();
  CHECK(widthAt(32) == 5);
  CHECK(pixelAt(32, 32) == Rgba{255, 255, 255, 255});
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("Colour sum without lighting adds the secondary colour after texturing") {
  ScopedContext context(8, 8);
  pixelProjection(8, 8);
  const GLubyte texel[4] = {128, 128, 128, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1.0f, 0.5f, 1.0f);
  glSecondaryColor3f(0.25f, 0.0f, 0.75f);
  glRectf(0.0f, 0.0f, 8.0f, 8.0f);
  const Rgba without = pixelAt(4, 4);
  CHECK(without.r == 128);
  CHECK(without.g == 64);
  glEnable(GL_COLOR_SUM);
  glRectf(0.0f, 0.0f, 8.0f, 8.0f);
  const Rgba with = pixelAt(4, 4);
  CHECK(with.r == 192);   // 0.502 + 0.25
  CHECK(with.g == 64);
  CHECK(with.b == 255);   // 0.502 + 0.75, clamped
  CHECK(with.a == 255);   // the secondary alpha is not added
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("glDrawBuffer(GL_NONE) writes no colour; glReadBuffer(GL_NONE) refuses colour reads") {
  ScopedContext context(8, 8);
  pixelProjection(8, 8);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);  // no colour buffer: nothing cleared
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.0f, 1.0f, 0.0f);
  depthQuad(4.0f, 0.5f);  // depth 0.25 written, colour not
  glDrawBuffer(GL_FRONT);
  glColor3f(1.0f, 1.0f, 0.0f);
  depthQuad(8.0f, 0.0f);  // depth 0.5: hidden where the first quad wrote depth
  glDisable(GL_DEPTH_TEST);
  CHECK(pixelAt(2, 4) == Rgba{0, 0, 255, 255});
  CHECK(pixelAt(6, 4) == Rgba{255, 255, 0, 255});
  CHECK(takeError() == GL_NO_ERROR);

  glReadBuffer(GL_NONE);
  GLubyte rgba[4] = {7, 7, 7, 7};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  CHECK(takeError() == GL_INVALID_OPERATION);
  CHECK(rgba[0] == 7);
  GLfloat depth = -1.0f;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  CHECK(takeError() == GL_NO_ERROR);
  CHECK(depth == doctest::Approx(0.25f));
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  CHECK(takeError() == GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 2, 2, GL_DEPTH);
  CHECK(takeError() == GL_NO_ERROR);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 2, 2, 0);
  CHECK(takeError() == GL_INVALID_OPERATION);
  glReadBuffer(GL_FRONT);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 2, 2, 0);
  CHECK(takeError() == GL_NO_ERROR);
  glReadBuffer(GL_NONE);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
  CHECK(takeError() == GL_INVALID_OPERATION);
  glDeleteTextures(1, &texture);
  glReadBuffer(GL_FRONT);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("Smooth points and lines at extreme sizes and positions draw without harm") {
  ScopedContext context(16, 16);
  pixelProjection(16, 16);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0F0F);
  glPointSize(1000.0f);  // clamped to 255
  glLineWidth(1000.0f);
  glBegin(GL_POINTS);
  glVertex2f(8.0f, 8.0f);
  glVertex2f(1e30f, 8.0f);
  glEnd();
  CHECK(pixelAt(0, 0) == Rgba{255, 255, 255, 255});
  glBegin(GL_LINES);
  glVertex2f(8.0f, 8.0f);
  glVertex2f(8.0f, 8.0f);  // zero length: nothing
  glVertex2f(-1e6f, 3.0f);
  glVertex2f(1e6f, 4.0f);  // clipped to the view volume first
  glEnd();
  const GLfloat attenuation[3] = {0.0f, 0.0f, 0.0f};  // 1 / 0: size clamped to the maximum
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glBegin(GL_POINTS);
  glVertex2f(8.0f, 8.0f);
  glEnd();
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("glAccum: GL_LOAD without a read buffer and GL_RETURN without a draw buffer do nothing") {
  ScopedContext context(4, 4);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadBuffer(GL_NONE);
  glAccum(GL_LOAD, 1.0f);  // reads nothing: the accumulation buffer stays 0
  glReadBuffer(GL_FRONT);
  glAccum(GL_RETURN, 1.0f);
  CHECK(pixelAt(1, 1) == Rgba{0, 0, 0, 0});
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_LOAD, 1.0f);
  glClearColor(1.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  glAccum(GL_RETURN, 1.0f);  // writes nothing
  glDrawBuffer(GL_FRONT);
  CHECK(pixelAt(1, 1) == Rgba{255, 255, 0, 255});
  CHECK(takeError() == GL_NO_ERROR);
}
