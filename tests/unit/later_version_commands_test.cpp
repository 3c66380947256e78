// Commands of OpenGL 1.2 to 1.4 that glass implements by definition through older ones, or
// accepts with the errors of a feature it lacks: glDrawRangeElements, glMultiDrawArrays,
// glMultiDrawElements, glLoadTransposeMatrix, glMultTransposeMatrix, the texture unit commands,
// glSampleCoverage and compressed textures (the imaging subset: pixels_imaging_test.cpp).
#include <doctest/doctest.h>

#include <GL/gl.h>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

GLint integerState(GLenum pname) {
  GLint v[4] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

// Two unit squares side by side in an 8 x 4 window: left (elements 0-3), right (4-7).
const GLfloat kSquares[16] = {-1, -1, 0, -1, 0, 1, -1, 1, 0, -1, 1, -1, 1, 1, 0, 1};

void setUpSquares() {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glVertexPointer(2, GL_FLOAT, 0, kSquares);
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor3f(1, 1, 1);
}

}  // namespace

TEST_CASE("glDrawRangeElements draws like glDrawElements; end < start is GL_INVALID_VALUE") {
  ScopedContext context(8, 4);
  setUpSquares();
  const GLubyte right[4] = {4, 5, 6, 7};
  glDrawRangeElements(GL_QUADS, 4, 7, 4, GL_UNSIGNED_BYTE, right);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(pixelAt(1, 2) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(6, 2) == Rgba{255, 255, 255, 255});

  glClear(GL_COLOR_BUFFER_BIT);
  const GLubyte left[4] = {0, 1, 2, 3};
  glDrawRangeElements(GL_QUADS, 3, 0, 4, GL_UNSIGNED_BYTE, left);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glDrawRangeElements(GL_QUADS, 0, 3, -1, GL_UNSIGNED_BYTE, left);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glDrawRangeElements(GL_QUADS, 0, 3, 4, GL_FLOAT, left);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glDrawRangeElements(GL_POLYGON + 1, 0, 3, 4, GL_UNSIGNED_BYTE, left);
  CHECK(glGetError() == GL_INVALID_ENUM);
  CHECK(pixelAt(1, 2) == Rgba{0, 0, 0, 0});
}

TEST_CASE("glMultiDrawArrays and glMultiDrawElements draw each range; zero counts are skipped") {
  ScopedContext context(8, 4);
  setUpSquares();
  const GLint first[2] = {0, 4};
  const GLsizei count[2] = {4, 0};
  glMultiDrawArrays(GL_QUADS, first, count, 2);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(pixelAt(1, 2) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(6, 2) == Rgba{0, 0, 0, 0});

  glClear(GL_COLOR_BUFFER_BIT);
  const GLushort left[4] = {0, 1, 2, 3}, right[4] = {4, 5, 6, 7};
  const GLvoid* lists[2] = {left, right};
  const GLsizei counts[2] = {4, 4};
  glMultiDrawElements(GL_QUADS, counts, GL_UNSIGNED_SHORT, lists, 2);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(pixelAt(1, 2) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(6, 2) == Rgba{255, 255, 255, 255});

  glMultiDrawArrays(GL_QUADS, first, count, -1);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMultiDrawElements(0x1234, counts, GL_UNSIGNED_SHORT, lists, 2);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("glDrawRangeElements inside a display list compiles the vertices it reads") {
  ScopedContext context(8, 4);
  setUpSquares();
  const GLubyte right[4] = {4, 5, 6, 7};
  glNewList(1, GL_COMPILE);
  glDrawRangeElements(GL_QUADS, 4, 7, 4, GL_UNSIGNED_BYTE, right);
  glEndList();
  CHECK(pixelAt(6, 2) == Rgba{0, 0, 0, 0});
  glDisableClientState(GL_VERTEX_ARRAY);
  glCallList(1);
  CHECK(pixelAt(6, 2) == Rgba{255, 255, 255, 255});
}

TEST_CASE("glLoadTransposeMatrix and glMultTransposeMatrix take the matrix row by row") {
  ScopedContext context;
  const GLfloat rows[16] = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};
  glLoadTransposeMatrixf(rows);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[12] == 5.0f);
  CHECK(m[13] == 6.0f);
  CHECK(m[14] == 7.0f);
  CHECK(m[3] == 0.0f);
  glGetFloatv(GL_TRANSPOSE_MODELVIEW_MATRIX, m);
  for (int i = 0; i < 16; ++i) CHECK(m[i] == rows[i]);

  const GLdouble scale[16] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1};
  glMultTransposeMatrixd(scale);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[0] == 2.0f);
  CHECK(m[5] == 3.0f);
  CHECK(m[12] == 5.0f);  // M * S keeps the translation

  const GLdouble shear[16] = {1, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // x += y
  glLoadTransposeMatrixd(shear);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[4] == 1.0f);  // column 1, row 0
  CHECK(m[1] == 0.0f);
  const GLfloat identityRows[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  glNewList(1, GL_COMPILE);
  glMultTransposeMatrixf(rows);
  glEndList();
  glLoadTransposeMatrixf(identityRows);
  glCallList(1);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[12] == 5.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Eight texture units: GL_TEXTURE0..7 are accepted, others are errors or ignored") {
  ScopedContext context;
  CHECK(integerState(GL_MAX_TEXTURE_UNITS) == 8);
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE0);
  CHECK(integerState(GL_CLIENT_ACTIVE_TEXTURE) == GL_TEXTURE0);
  glActiveTexture(GL_TEXTURE0);
  glClientActiveTexture(GL_TEXTURE0);
  glActiveTextureARB(GL_TEXTURE0_ARB);
  CHECK(glGetError() == GL_NO_ERROR);
  glActiveTexture(GL_TEXTURE8);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glClientActiveTexture(GL_TEXTURE8);
  CHECK(glGetError() == GL_INVALID_ENUM);
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE0);

  GLfloat tc[4];
  glMultiTexCoord2f(GL_TEXTURE0, 0.25f, 0.5f);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.25f);
  CHECK(tc[1] == 0.5f);
  CHECK(tc[2] == 0.0f);
  CHECK(tc[3] == 1.0f);
  const GLshort s4[4] = {1, 2, 3, 4};
  glMultiTexCoord4svARB(GL_TEXTURE0_ARB, s4);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[3] == 4.0f);
  glMultiTexCoord1d(GL_TEXTURE0, 0.75);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.75f);
  CHECK(tc[1] == 0.0f);
  CHECK(tc[3] == 1.0f);
  // Coordinates for a unit glass does not have change nothing, and another unit's leave unit 0's.
  glMultiTexCoord2f(GL_TEXTURE8, 9.0f, 9.0f);
  glMultiTexCoord2f(GL_TEXTURE3, 9.0f, 9.0f);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.75f);
  CHECK(glGetError() == GL_NO_ERROR);

  glNewList(1, GL_COMPILE);
  glMultiTexCoord3i(GL_TEXTURE0, 5, 6, 7);
  glEndList();
  glCallList(1);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[2] == 7.0f);
}

TEST_CASE("glSampleCoverage and the multisample enables are state, saved by GL_MULTISAMPLE_BIT") {
  ScopedContext context;
  CHECK(integerState(GL_SAMPLE_BUFFERS) == 0);
  CHECK(glIsEnabled(GL_MULTISAMPLE) == GL_TRUE);
  CHECK(glIsEnabled(GL_SAMPLE_COVERAGE) == GL_FALSE);
  GLfloat value = 0.0f;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
  CHECK(value == 1.0f);
  glSampleCoverage(0.5f, GL_TRUE);
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
  CHECK(value == 0.5f);
  GLboolean invert = GL_FALSE;
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &invert);
  CHECK(invert == GL_TRUE);
  glSampleCoverage(2.0f, GL_FALSE);  // clamped to [0, 1]
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
  CHECK(value == 1.0f);

  glPushAttrib(GL_MULTISAMPLE_BIT);
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glSampleCoverage(0.25f, GL_TRUE);
  glPopAttrib();
  CHECK(glIsEnabled(GL_MULTISAMPLE) == GL_TRUE);
  CHECK(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE) == GL_FALSE);
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
  CHECK(value == 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Compressed texture commands fail with the errors of unsupported formats") {
  ScopedContext context;
  const GLubyte data[64] = {};
  CHECK(integerState(GL_NUM_COMPRESSED_TEXTURE_FORMATS) == 0);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, GL_COMPRESSED_RGB, 8, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  GLubyte out[64];
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, out);
  CHECK(glGetError() == GL_INVALID_VALUE);

}
