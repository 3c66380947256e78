// glGet of the raster position, pixel transfer, pixel map and zoom state (tables 6.5, 6.16, 6.17).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// False when pname is none of these.
bool queryPixelState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
