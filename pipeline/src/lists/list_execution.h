// Compiling and executing display lists (spec 5.4).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// glCallList's work: runs the commands of list `name`, if it exists, unless the nesting of
// glCallList already reached GL_MAX_LIST_NESTING.
void callList(Context& ctx, GLuint name);

// glGenLists' work: reserves `range` consecutive unused names (each an empty list) and returns
// the first, or 0 when there is no such range.
GLuint generateLists(Context& ctx, GLsizei range);

}  // namespace glass::gl
