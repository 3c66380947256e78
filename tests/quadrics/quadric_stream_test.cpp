// glass's GLU quadrics against the SGI GLU that Mesa ships (libGLU), call by call and bit by bit.
//
// This program links libGLU but not libglass: it defines the few GL entry points GLU's quadrics
// call (glBegin, glEnd, glNormal3f, glTexCoord2f, glVertex3f), so every call GLU makes is
// recorded here. glass's generators (compiled straight into this program) record into the same
// kind of list through a PrimitiveEmitter. The two lists must be identical.
#include <doctest/doctest.h>

#include <GL/glu.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "glu/quadric_emitter.h"

namespace {

struct Call {
  char kind;  // 'B'egin, 'E'nd, 'N'ormal, 'T'exCoord, 'V'ertex
  unsigned mode;
  float v[3];
  bool operator==(const Call& o) const {
    return kind == o.kind && mode == o.mode && std::memcmp(v, o.v, sizeof v) == 0;
  }
};

std::vector<Call> g_recorded;

class Recorder : public glass::gl::glu::PrimitiveEmitter {
 public:
  std::vector<Call> calls;
  void begin(GLenum mode) override { calls.push_back({'B', mode, {0, 0, 0}}); }
  void normal(float x, float y, float z) override { calls.push_back({'N', 0, {x, y, z}}); }
  void texCoord(float s, float t) override { calls.push_back({'T', 0, {s, t, 0}}); }
  void vertex(float x, float y, float z) override { calls.push_back({'V', 0, {x, y, z}}); }
  void end() override { calls.push_back({'E', 0, {0, 0, 0}}); }
};

std::string describe(const Call& c) {
  char text[160];
  std::snprintf(text, sizeof text, "%c %u %a %a %a", c.kind, c.mode, c.v[0], c.v[1], c.v[2]);
  return text;
}

// Compares the streams and reports the first difference.
void checkSameStream(const std::vector<Call>& glu, const std::vector<Call>& glass) {
  const size_t n = glu.size() < glass.size() ? glu.size() : glass.size();
  for (size_t k = 0; k < n; ++k) {
    if (!(glu[k] == glass[k])) {
      INFO("call " << k << ": GLU " << describe(glu[k]) << ", glass " << describe(glass[k]));
      CHECK(false);
      return;
    }
  }
  CHECK(glu.size() == glass.size());
  CHECK(!glu.empty());
}

struct Styles {
  GLenum normals, orientation, drawStyle;
  bool texture;
};

std::vector<Styles> allStyles() {
  std::vector<Styles> out;
  for (GLenum normals : {GLU_SMOOTH, GLU_FLAT, GLU_NONE})
    for (GLenum orientation : {GLU_OUTSIDE, GLU_INSIDE})
      for (GLenum drawStyle : {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT})
        for (bool texture : {false, true}) {
          out.push_back({normals, orientation, drawStyle, texture});
        }
  return out;
}

// GLU reads table entries it never filled for a few combinations (flat normals with points, and
// with the silhouette of a cylinder or sphere): those streams are left out of the comparison.
bool gluLeavesUndefined(const Styles& s, bool sphereOrCylinder) {
  if (s.normals != GLU_FLAT) return false;
  if (s.drawStyle == GLU_POINT) return sphereOrCylinder;
  return s.drawStyle == GLU_SILHOUETTE && sphereOrCylinder;
}

GLUquadric* gluQuadricWith(const Styles& s) {
  GLUquadric* q = gluNewQuadric();
  gluQuadricNormals(q, s.normals);
  gluQuadricOrientation(q, s.orientation);
  gluQuadricDrawStyle(q, s.drawStyle);
  gluQuadricTexture(q, s.texture ? GL_TRUE : GL_FALSE);
  return q;
}

glass::gl::glu::QuadricStyle glassStyleWith(const Styles& s) {
  glass::gl::glu::QuadricStyle style;
  style.normals = s.normals;
  style.orientation = s.orientation;
  style.drawStyle = s.drawStyle;
  style.textureCoords = s.texture;
  return style;
}

std::string name(const Styles& s) {
  char text[96];
  std::snprintf(text, sizeof text, "normals %u orientation %u style %u texture %d", s.normals,
                s.orientation, s.drawStyle, s.texture ? 1 : 0);
  return text;
}

}  // namespace

// The GL entry points libGLU calls, recorded.
extern "C" {
void glBegin(GLenum mode) { g_recorded.push_back({'B', mode, {0, 0, 0}}); }
void glEnd(void) { g_recorded.push_back({'E', 0, {0, 0, 0}}); }
void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { g_recorded.push_back({'N', 0, {x, y, z}}); }
void glTexCoord2f(GLfloat s, GLfloat t) { g_recorded.push_back({'T', 0, {s, t, 0}}); }
void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { g_recorded.push_back({'V', 0, {x, y, z}}); }
}

TEST_CASE("gluSphere: glass emits GLU's stream for every style") {
  const struct { double radius; int slices, stacks; } sizes[] = {
      {1.0, 7, 5}, {2.5, 32, 16}, {0.75, 3, 1}, {1.0, 12, 12}, {1.3, 5, 9}, {1.0, 300, 2}};
  for (const Styles& s : allStyles()) {
    if (gluLeavesUndefined(s, true)) continue;
    for (const auto& size : sizes) {
      if (size.stacks > size.slices && s.normals == GLU_SMOOTH && s.drawStyle == GLU_FILL &&
          !s.texture) {
        continue;  // GLU's south-pole normal reads a longitude entry beyond the table
      }
      INFO(name(s) << " radius " << size.radius << " " << size.slices << "x" << size.stacks);
      g_recorded.clear();
      GLUquadric* q = gluQuadricWith(s);
      gluSphere(q, size.radius, size.slices, size.stacks);
      gluDeleteQuadric(q);
      Recorder glass;
      CHECK(glass::gl::glu::emitSphere(glassStyleWith(s), size.radius, size.slices, size.stacks,
                                       glass));
      checkSameStream(g_recorded, glass.calls);
    }
  }
}

TEST_CASE("gluCylinder: glass emits GLU's stream for every style") {
  const struct { double base, top, height; int slices, stacks; } sizes[] = {
      {1.0, 1.0, 2.0, 8, 3}, {1.0, 0.0, 1.5, 16, 4}, {0.3, 1.2, 0.7, 5, 1},
      {2.0, 1.0, 0.0, 24, 2}, {1.0, 1.0, 3.0, 400, 2}};
  for (const Styles& s : allStyles()) {
    if (gluLeavesUndefined(s, true)) continue;
    for (const auto& size : sizes) {
      INFO(name(s) << " " << size.base << " " << size.top << " " << size.height << " "
                   << size.slices << "x" << size.stacks);
      g_recorded.clear();
      GLUquadric* q = gluQuadricWith(s);
      gluCylinder(q, size.base, size.top, size.height, size.slices, size.stacks);
      gluDeleteQuadric(q);
      Recorder glass;
      CHECK(glass::gl::glu::emitCylinder(glassStyleWith(s), size.base, size.top, size.height,
                                         size.slices, size.stacks, glass));
      checkSameStream(g_recorded, glass.calls);
    }
  }
}

TEST_CASE("gluDisk and gluPartialDisk: glass emits GLU's stream for every style") {
  const struct { double inner, outer; int slices, loops; double start, sweep; } sizes[] = {
      {0.0, 1.0, 8, 3, 0, 360},     {0.5, 2.0, 16, 2, 0, 360},   {0.25, 1.0, 10, 4, 30, 120},
      {0.0, 1.5, 6, 1, -45, -200},  {1.0, 1.0, 12, 2, 0, 360},   {1.0, 1.0, 12, 2, 10, 90},
      {0.2, 0.9, 5, 3, 15, 720},    {0.0, 2.0, 20, 5, 90, -400}};
  for (const Styles& s : allStyles()) {
    for (const auto& size : sizes) {
      INFO(name(s) << " " << size.inner << " " << size.outer << " " << size.slices << "x"
                   << size.loops << " from " << size.start << " sweep " << size.sweep);
      g_recorded.clear();
      GLUquadric* q = gluQuadricWith(s);
      gluPartialDisk(q, size.inner, size.outer, size.slices, size.loops, size.start, size.sweep);
      gluDeleteQuadric(q);
      Recorder glass;
      CHECK(glass::gl::glu::emitPartialDisk(glassStyleWith(s), size.inner, size.outer,
                                            size.slices, size.loops, size.start, size.sweep,
                                            glass));
      checkSameStream(g_recorded, glass.calls);
    }
  }
}

TEST_CASE("quadrics: GLU's invalid values are rejected without drawing") {
  Recorder glass;
  const glass::gl::glu::QuadricStyle style;
  CHECK_FALSE(glass::gl::glu::emitSphere(style, -1.0, 8, 8, glass));
  CHECK_FALSE(glass::gl::glu::emitSphere(style, 1.0, 1, 8, glass));
  CHECK_FALSE(glass::gl::glu::emitSphere(style, 1.0, 8, 0, glass));
  CHECK_FALSE(glass::gl::glu::emitCylinder(style, 1.0, 1.0, -1.0, 8, 1, glass));
  CHECK_FALSE(glass::gl::glu::emitCylinder(style, 0.0, 0.0, 0.0, 8, 1, glass));
  CHECK_FALSE(glass::gl::glu::emitPartialDisk(style, 2.0, 1.0, 8, 1, 0, 360, glass));
  CHECK_FALSE(glass::gl::glu::emitPartialDisk(style, 0.0, 0.0, 8, 1, 0, 360, glass));
  CHECK(glass.calls.empty());
}
