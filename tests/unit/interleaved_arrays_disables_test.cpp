// glInterleavedArrays (OpenGL 1.4 specification, section 2.8): its effect begins with
// DisableClientState(EDGE_FLAG_ARRAY) and DisableClientState(INDEX_ARRAY), whatever the format.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

TEST_CASE("glInterleavedArrays disables the edge flag and colour index arrays") {
  ScopedContext context(8, 8);
  static GLfloat data[64];
  for (GLenum format : {GL_V2F, GL_C4UB_V3F, GL_T2F_C4F_N3F_V3F}) {
    INFO("format " << format);
    glEnableClientState(GL_INDEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glInterleavedArrays(format, 0, data);
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK(glIsEnabled(GL_INDEX_ARRAY) == GL_FALSE);
    CHECK(glIsEnabled(GL_EDGE_FLAG_ARRAY) == GL_FALSE);
    CHECK(glIsEnabled(GL_VERTEX_ARRAY) == GL_TRUE);
  }
  // A refused call changes nothing.
  glEnableClientState(GL_INDEX_ARRAY);
  glInterleavedArrays(GL_V2F, -1, data);
  CHECK(glGetError() == GL_INVALID_VALUE);
  CHECK(glIsEnabled(GL_INDEX_ARRAY) == GL_TRUE);
}
