// glGet (spec 6.1): finds the value of a piece of state. The core's state is answered in
// state_query.cpp; lighting, fog and texturing answer for theirs through their hooks; every
// capability of glIsEnabled is also a glGet name.
#pragma once

#include <GL/gl.h>

#include "core/state_value.h"

namespace glass::gl {

struct Context;

// Returns false when pname names no state (GL_INVALID_ENUM).
bool queryState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
