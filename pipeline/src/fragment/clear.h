// glClear (spec 4.2.3): sets the selected buffers to their clear values inside the scissor box
// (when the scissor test is enabled), through the colour, depth and stencil write masks.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// mask: GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT, GL_ACCUM_BUFFER_BIT.
// Nothing is cleared in GL_SELECT and GL_FEEDBACK render modes.
void clearBuffers(Context& ctx, GLbitfield mask);

}  // namespace glass::gl
