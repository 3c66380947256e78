// The texturing commands through the GL API: the errors the specification lists, state queries,
// texture object lifetime, GLU mipmaps, a few texels rendered at known positions, and bump
// mapping against normals worked out by hand.
#include <GL/gl.h>
#include <GL/glu.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <cstdlib>
#include <functional>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::ScopedContext;

namespace {

struct ErrorCase {
  const char* call;
  std::function<void()> run;
  GLenum expected;
};

void checkErrors(const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& c : cases) {
    INFO(c.call);
    REQUIRE(glGetError() == GL_NO_ERROR);
    c.run();
    CHECK(glGetError() == c.expected);
    CHECK(glGetError() == GL_NO_ERROR);
  }
}

const GLubyte kTexels[4 * 4 * 4] = {};

// Draws a textured quad covering pixels [x0, x0 + w) x [y0, y0 + h), texture coordinates 0..1.
void texturedQuad(int x0, int y0, int w, int h) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(x0, y0);
  glTexCoord2f(1, 0);
  glVertex2i(x0 + w, y0);
  glTexCoord2f(1, 1);
  glVertex2i(x0 + w, y0 + h);
  glTexCoord2f(0, 1);
  glVertex2i(x0, y0 + h);
  glEnd();
}

bool near(int a, int b, int tolerance = 1) { return std::abs(a - b) <= tolerance; }

}  // namespace

TEST_CASE("texture errors: objects, images and sub-images") {
  ScopedContext context;
  GLuint names[2];
  glGenTextures(2, names);
  glBindTexture(GL_TEXTURE_1D, names[0]);
  glBindTexture(GL_TEXTURE_2D, 0);
  checkErrors({
      {"glGenTextures(-1)", [&] { glGenTextures(-1, names); }, GL_INVALID_VALUE},
      {"glDeleteTextures(-1)", [&] { glDeleteTextures(-1, names); }, GL_INVALID_VALUE},
      {"glBindTexture(bad target)", [&] { glBindTexture(GL_PROXY_TEXTURE_2D, names[1]); }, GL_INVALID_ENUM},
      {"glBindTexture(1D name as 2D)", [&] { glBindTexture(GL_TEXTURE_2D, names[0]); }, GL_INVALID_OPERATION},
      {"glTexImage2D(bad target)",
       [] { glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_ENUM},
      {"glTexImage2D(level -1)",
       [] { glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexImage2D(level 13)",
       [] { glTexImage2D(GL_TEXTURE_2D, 13, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexImage2D(bad internal format)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexImage2D(border 2)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexImage2D(width -1)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexImage2D(width 8192)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8192, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr); },
       GL_INVALID_VALUE},
      {"glTexImage2D(bad format)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA8, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_ENUM},
      // Depth data for a colour internal format (GL 1.4, 3.8.1; ARB_depth_texture).
      {"glTexImage2D(GL_DEPTH_COMPONENT)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_OPERATION},
      {"glTexImage2D(bad type)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_RGBA, kTexels); }, GL_INVALID_ENUM},
      {"glTexImage2D(5_6_5 with RGBA)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, kTexels); },
       GL_INVALID_OPERATION},
      {"glTexImage1D(bad target)",
       [] { glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_ENUM},
      {"glTexSubImage2D(no image)",
       [] { glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_OPERATION},
      {"glTexImage2D(valid)",
       [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_NO_ERROR},
      {"glTexSubImage2D(outside)",
       [] { glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glTexSubImage2D(negative offset)",
       [] { glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kTexels); },
       GL_INVALID_VALUE},
      {"glCopyTexImage2D(internal format 3)", [] { glCopyTexImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 4, 4, 0); },
       GL_INVALID_VALUE},
      {"glCopyTexImage2D(proxy target)",
       [] { glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0); }, GL_INVALID_ENUM},
      {"glGetTexImage(level -1)",
       [] { GLubyte b[64]; glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, b); },
       GL_INVALID_VALUE},
      {"glGetTexLevelParameteriv(bad target)",
       [] { GLint v; glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v); }, GL_INVALID_ENUM},
      {"glGetTexLevelParameteriv(bad pname)",
       [] { GLint v; glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v); }, GL_INVALID_ENUM},
  });
}

TEST_CASE("texture errors: parameters, environment, generation, begin/end") {
  ScopedContext context;
  const GLfloat color[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  checkErrors({
      {"glTexParameteri(bad target)", [] { glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR); },
       GL_INVALID_ENUM},
      {"glTexParameteri(bad pname)", [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_LINEAR); },
       GL_INVALID_ENUM},
      {"glTexParameteri(MIN_FILTER, bad)", [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT); },
       GL_INVALID_ENUM},
      {"glTexParameteri(MAG_FILTER, mipmap)",
       [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR); }, GL_INVALID_ENUM},
      {"glTexParameteri(WRAP_S, bad)", [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR); },
       GL_INVALID_ENUM},
      {"glTexParameteri(BASE_LEVEL, -1)", [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1); },
       GL_INVALID_VALUE},
      {"glTexParameteri(MAX_LEVEL, -1)", [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1); },
       GL_INVALID_VALUE},
      {"glTexParameterf(BORDER_COLOR) scalar",
       [] { glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.0f); }, GL_INVALID_ENUM},
      {"glTexParameterfv(BORDER_COLOR)",
       [&] { glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, color); }, GL_NO_ERROR},
      {"glTexEnvi(bad target)", [] { glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_MODULATE); },
       GL_INVALID_ENUM},
      {"glTexEnvi(bad mode)", [] { glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR); }, GL_INVALID_ENUM},
      {"glTexEnvf(ENV_COLOR) scalar", [] { glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 1.0f); },
       GL_INVALID_ENUM},
      {"glTexGeni(bad coord)", [] { glTexGeni(GL_TEXTURE_2D, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR); },
       GL_INVALID_ENUM},
      {"glTexGeni(R, SPHERE_MAP)", [] { glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP); }, GL_INVALID_ENUM},
      {"glTexGeni(S, bad mode)", [] { glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR); }, GL_INVALID_ENUM},
      {"glTexGenf(OBJECT_PLANE) scalar", [] { glTexGenf(GL_S, GL_OBJECT_PLANE, 1.0f); }, GL_INVALID_ENUM},
      {"glTexGeni(Q, SPHERE_MAP... S is fine)", [] { glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP); },
       GL_NO_ERROR},
      {"glBindTexture inside glBegin/glEnd",
       [] {
         glBegin(GL_POINTS);
         glBindTexture(GL_TEXTURE_2D, 0);
         glEnd();
       },
       GL_INVALID_OPERATION},
      {"glTexImage2D inside glBegin/glEnd",
       [] {
         glBegin(GL_POINTS);
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTexels);
         glEnd();
       },
       GL_INVALID_OPERATION},
  });
}

TEST_CASE("texture objects: names, binding, deletion") {
  ScopedContext context;
  GLuint names[3];
  glGenTextures(3, names);
  CHECK(names[0] != 0);
  CHECK(names[0] != names[1]);
  CHECK(names[1] != names[2]);
  // Generated names are not textures until they are bound (spec 3.8.12).
  CHECK(glIsTexture(names[0]) == GL_FALSE);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  CHECK(glIsTexture(names[0]) == GL_TRUE);
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  CHECK(bound == static_cast<GLint>(names[0]));
  // A new name from glGenTextures is never one in use.
  GLuint more[2];
  glGenTextures(2, more);
  for (GLuint n : more)
    for (GLuint m : names) CHECK(n != m);
  // Deleting the bound texture binds the default texture.
  glDeleteTextures(1, &names[0]);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  CHECK(bound == 0);
  CHECK(glIsTexture(names[0]) == GL_FALSE);
  CHECK(glIsTexture(0) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("texture state queries: defaults, level parameters, proxies") {
  ScopedContext context;
  GLint v = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  CHECK(v == GL_NEAREST_MIPMAP_LINEAR);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &v);
  CHECK(v == GL_LINEAR);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v);
  CHECK(v == GL_REPEAT);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &v);
  CHECK(v == 1000);
  GLfloat f[4] = {-1, -1, -1, -1};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, f);
  CHECK(f[0] == -1000.0f);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  CHECK(v == GL_MODULATE);
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &v);
  CHECK(v == GL_EYE_LINEAR);
  glGetTexGenfv(GL_T, GL_OBJECT_PLANE, f);
  CHECK(f[0] == 0.0f);
  CHECK(f[1] == 1.0f);
  GLboolean enabled = GL_TRUE;
  glGetBooleanv(GL_TEXTURE_2D, &enabled);
  CHECK(enabled == GL_FALSE);
  glEnable(GL_TEXTURE_GEN_Q);
  CHECK(glIsEnabled(GL_TEXTURE_GEN_Q) == GL_TRUE);

  // A 6 x 4 image with a border of 1 has 4 x 2 texels inside; widths include the border.
  std::vector<GLubyte> texels(6 * 4 * 3, 200);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 6, 4, 1, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  CHECK(v == 6);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BORDER, &v);
  CHECK(v == 1);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == GL_RGB8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &v);
  CHECK(v == 8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &v);
  CHECK(v == 0);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &v);
  CHECK(v == 0);

  // Proxies: a size that fits is recorded, one that does not leaves zeros, neither is an error.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 512, 256, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &v);
  CHECK(v == 256);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8192, 8192, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  CHECK(v == 0);
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  CHECK(maxSize >= 64);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glGetTexImage returns the texels as specified, converted per table 6.1") {
  ScopedContext context;
  const GLubyte rgb[3 * 3] = {10, 20, 30, 40, 50, 60, 70, 80, 90};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  GLubyte back[3 * 4] = {};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  CHECK(back[4] == 40);
  CHECK(back[6] == 60);
  CHECK(back[7] == 255);  // RGB has no alpha: 1

  // A luminance texture comes back as L in red (table 6.1), and as luminance again.
  const GLubyte lum[2] = {77, 200};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, back);
  CHECK(back[0] == 77);
  CHECK(back[1] == 0);
  CHECK(back[3] == 200);
  GLfloat asFloat[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_FLOAT, asFloat);
  CHECK(asFloat[1] == doctest::Approx(200.0 / 255.0));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("gluBuild2DMipmaps halves with GLU's (a + b + c + d + 2) / 4 and rounds sizes to powers of two") {
  ScopedContext context;
  const GLubyte image[4 * 4] = {0, 255, 10, 11,  //
                                0, 0,   12, 13,  //
                                1, 2,   3,  4,   //
                                5, 6,   7,  8};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  CHECK(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_LUMINANCE, 4, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, image) == 0);
  GLubyte level1[4] = {}, level2[1] = {};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, level1);
  glGetTexImage(GL_TEXTURE_2D, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, level2);
  CHECK(level1[0] == 64);  // (0 + 255 + 0 + 0 + 2) / 4
  CHECK(level1[1] == 12);  // (10 + 11 + 12 + 13 + 2) / 4
  CHECK(level1[2] == 4);   // (1 + 2 + 5 + 6 + 2) / 4
  CHECK(level1[3] == 6);   // (3 + 4 + 7 + 8 + 2) / 4
  CHECK(level2[0] == 22);  // (64 + 12 + 4 + 6 + 2) / 4

  // 3 x 5: GLU rounds 3 up to 4 and 5 down to 4; the chain then ends at 1 x 1 (level 2).
  std::vector<GLubyte> odd(3 * 5, 100);
  CHECK(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_LUMINANCE, 3, 5, GL_LUMINANCE, GL_UNSIGNED_BYTE, odd.data()) == 0);
  GLint w = 0, h = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  CHECK(w == 4);
  CHECK(h == 4);
  glGetTexImage(GL_TEXTURE_2D, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, level2);
  CHECK(level2[0] == 100);  // a uniform image stays uniform through the box filters

  CHECK(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 4, 4, GL_RGB8, GL_UNSIGNED_BYTE, image) == GLU_INVALID_ENUM);
  CHECK(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 0, 4, GL_RGB, GL_UNSIGNED_BYTE, image) == GLU_INVALID_VALUE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("gluScaleImage interpolates when enlarging, with boxes that wrap, and averages when reducing") {
  ScopedContext context;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // 2 x 1 -> 4 x 1: centres 0.25, 0.75, 1.25, 1.75 source texels, each a box one texel wide. The
  // first box reaches to -0.25, which wraps to texel 1: a quarter of 65535, (16383.75 + 1/2) /
  // 1 truncated is 16384, 64 as a byte.
  const GLubyte ramp[2] = {0, 255};
  GLubyte enlarged[4] = {};
  CHECK(gluScaleImage(GL_LUMINANCE, 2, 1, GL_UNSIGNED_BYTE, ramp, 4, 1, GL_UNSIGNED_BYTE, enlarged) == 0);
  CHECK(enlarged[0] == 64);
  CHECK(enlarged[1] == 64);
  CHECK(enlarged[2] == 191);  // (49151.25 + 1/2) truncated is 49151, >> 8
  CHECK(enlarged[3] == 191);  // the last box wraps to texel 0
  // Exactly half: (0 + 3 * 65535 + 2) / 4 = 49151.
  const GLubyte square[4] = {0, 255, 255, 255};
  GLubyte halved[1] = {};
  CHECK(gluScaleImage(GL_LUMINANCE, 2, 2, GL_UNSIGNED_BYTE, square, 1, 1, GL_UNSIGNED_BYTE, halved) == 0);
  CHECK(halved[0] == 191);
  // 3 x 1 -> 1 x 1: one box over all three, (65535 + 1/2) / 3 truncated is 21845.
  const GLubyte three[3] = {0, 0, 255};
  GLubyte reduced[1] = {};
  CHECK(gluScaleImage(GL_LUMINANCE, 3, 1, GL_UNSIGNED_BYTE, three, 1, 1, GL_UNSIGNED_BYTE, reduced) == 0);
  CHECK(reduced[0] == 85);
  // Floats come back as 16-bit values over 65535.
  GLfloat asFloat[4] = {};
  CHECK(gluScaleImage(GL_LUMINANCE, 2, 1, GL_UNSIGNED_BYTE, ramp, 4, 1, GL_FLOAT, asFloat) == 0);
  CHECK(asFloat[0] == doctest::Approx(16384.0 / 65535.0).epsilon(1e-7));
  CHECK(gluScaleImage(GL_LUMINANCE, 2, 1, GL_UNSIGNED_BYTE, ramp, 4, 1, GL_UNSIGNED_SHORT_5_6_5, enlarged) ==
        GLU_INVALID_ENUM);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("NEAREST and LINEAR texels land where the specification's formulas put them") {
  ScopedContext context(16, 16);
  pixelProjection(16, 16);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  // 2 x 1 texels, black and white, on 4 x 1 pixels. Pixel x has u = 2 (x + 1/2) / 4.
  const GLubyte texels[2] = {0, 255};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  texturedQuad(0, 0, 4, 1);
  CHECK(pixelAt(0, 0).r == 0);
  CHECK(pixelAt(1, 0).r == 0);
  CHECK(pixelAt(2, 0).r == 255);
  CHECK(pixelAt(3, 0).r == 255);

  // LINEAR: i0 = floor(u - 1/2), alpha = frac(u - 1/2); u - 1/2 = -0.25, 0.25, 0.75, 1.25.
  // Clamped to the edge, the weights of the white texel are 0, 0.25, 0.75 and 1.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  texturedQuad(0, 2, 4, 1);
  CHECK(pixelAt(0, 2).r == 0);
  CHECK(near(pixelAt(1, 2).r, 64));
  CHECK(near(pixelAt(2, 2).r, 191));
  CHECK(pixelAt(3, 2).r == 255);

  // CLAMP_TO_BORDER with LINEAR: at the first pixel half of the weight goes to the border texel
  // i = -1 (border colour grey 0.4): 0.75 * 0 + 0.25 * 0.4 ... u - 1/2 = -0.25: i0 = -1 with
  // weight 0.25, i1 = 0 (black) with 0.75.
  const GLfloat grey[4] = {0.4f, 0.4f, 0.4f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, grey);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  texturedQuad(0, 4, 4, 1);
  CHECK(near(pixelAt(0, 4).r, 26));  // 0.25 * 102
  CHECK(near(pixelAt(3, 4).r, 217));  // 0.75 * 255 + 0.25 * 102

  // An incomplete texture (mipmapped minification, no level 1) turns texturing off: the
  // fragment colour shows.
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glColor3ub(10, 200, 30);
  texturedQuad(0, 6, 4, 1);
  CHECK(pixelAt(1, 6) == glass::test::Rgba{10, 200, 30, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("bump mapping tilts the normal by the height map's slope") {
  // A quad facing the viewer under glOrtho(-1, 1, ...): P_s = (2, 0, 0), P_t = (0, 2, 0) per unit
  // of s and t, N = (0, 0, 1). The height map rises linearly in s: 16 texels of 0, 17, ..., 255,
  // so dh/ds = 17/255 * 16 = 16/15; with GL_BUMP_SCALE_GLASS 15/8, d_s = 2 and d_t = 0.
  // n* = N + d_s (N x P_t) / |P_s x P_t| = (0, 0, 1) + 2 (-2, 0, 0) / 4 = (-1, 0, 1), normalized
  // (-1, 0, 1) / sqrt 2. Lit by a directional light from (1, 0, 1) (diffuse only) it faces away
  // (N.L = 0); from (-1, 0, 1) it faces the light (N.L = 1); flat, either gives 1 / sqrt 2.
  ScopedContext context(32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  GLubyte ramp[2][16];
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 16; ++i) ramp[j][i] = static_cast<GLubyte>(17 * i);
  GLuint heightMap = 0;
  glGenTextures(1, &heightMap);
  glBindTexture(GL_TEXTURE_2D, heightMap);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  glMaterialfv(GL_FRONT, GL_AMBIENT, black);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  glShadeModel(GL_PHONG_WIN);
  glEnable(GL_BUMP_MAP_GLASS);
  glTexEnvi(GL_BUMP_MAP_GLASS, GL_BUMP_MAP_TEXTURE_GLASS, static_cast<GLint>(heightMap));
  glTexEnvf(GL_BUMP_MAP_GLASS, GL_BUMP_SCALE_GLASS, 15.0f / 8.0f);
  GLfloat scale = 0;
  glGetTexEnvfv(GL_BUMP_MAP_GLASS, GL_BUMP_SCALE_GLASS, &scale);
  CHECK(scale == 15.0f / 8.0f);

  const auto litQuad = [](float lx, float lz) {
    const GLfloat direction[4] = {lx, 0.0f, lz, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, direction);
    glClear(GL_COLOR_BUFFER_BIT);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glTexCoord2f(0, 1);
    glVertex2f(-1, 1);
    glEnd();
    return pixelAt(16, 16).r;
  };
  CHECK(litQuad(1, 1) <= 2);
  CHECK(near(litQuad(-1, 1), 255, 2));
  glDisable(GL_BUMP_MAP_GLASS);
  CHECK(near(litQuad(1, 1), 180, 2));  // 255 / sqrt 2
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("display lists compile texture commands with the pixels of compile time") {
  ScopedContext context;
  GLuint texture = 0;
  glGenTextures(1, &texture);
  GLubyte texel[4] = {255, 0, 0, 255};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glEndList();
  // GL_COMPILE did not execute anything, and the client's memory changes before the call.
  CHECK(glIsTexture(texture) == GL_FALSE);
  texel[0] = 0;
  texel[1] = 255;
  glCallList(list);
  CHECK(glIsTexture(texture) == GL_TRUE);
  GLubyte back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  CHECK(back[0] == 255);
  CHECK(back[1] == 0);
  GLint value = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &value);
  CHECK(value == GL_NEAREST);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &value);
  CHECK(value == GL_DECAL);
  glDeleteLists(list, 1);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("points and lines are textured with the base level, magnified") {
  ScopedContext context(16, 16);
  pixelProjection(16, 16);
  const GLubyte texels[2] = {40, 220};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  // A mipmapped minification filter would need more levels; the texture must be complete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_POINTS);
  glTexCoord2f(0.25f, 0.5f);
  glVertex2f(2.5f, 2.5f);
  glTexCoord2f(0.75f, 0.5f);
  glVertex2f(5.5f, 2.5f);
  glEnd();
  CHECK(pixelAt(2, 2).r == 40);
  CHECK(pixelAt(5, 2).r == 220);
  // A horizontal line from s = 0 to s = 1 across 8 pixels: the first half dark, the second light.
  glBegin(GL_LINES);
  glTexCoord2f(0.0f, 0.5f);
  glVertex2f(0.0f, 8.5f);
  glTexCoord2f(1.0f, 0.5f);
  glVertex2f(8.0f, 8.5f);
  glEnd();
  CHECK(pixelAt(1, 8).r == 40);
  CHECK(pixelAt(6, 8).r == 220);
  CHECK(glGetError() == GL_NO_ERROR);
}
