// Colour index mode state in an RGBA context (spec 2.7, 4.2.2, 4.2.3; tables 6.5, 6.6, 6.21).
//
// glass has only RGBA framebuffers, so colour index rendering never happens. The colour index
// commands are still accepted, as Mesa accepts them in an RGBA context: glIndex sets the current
// index, glClearIndex and glIndexMask set their state, glIndexPointer and GL_INDEX_ARRAY set a
// client array that no draw reads, and all of it can be queried. Nothing of it changes a pixel.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// glGet of GL_CURRENT_INDEX, GL_INDEX_CLEAR_VALUE, GL_INDEX_WRITEMASK, GL_INDEX_ARRAY_TYPE and
// GL_INDEX_ARRAY_STRIDE. False when pname is none of these.
bool queryColorIndexState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
