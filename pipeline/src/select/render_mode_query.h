// glGet of the render mode state (table 6.31): GL_RENDER_MODE, GL_NAME_STACK_DEPTH,
// GL_MAX_NAME_STACK_DEPTH, GL_SELECTION_BUFFER_SIZE, GL_FEEDBACK_BUFFER_SIZE and
// GL_FEEDBACK_BUFFER_TYPE; and glGetPointerv of the two buffers.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// False when pname is none of these.
bool queryRenderModeState(const Context& ctx, GLenum pname, StateValue& value);

// GL_SELECTION_BUFFER_POINTER and GL_FEEDBACK_BUFFER_POINTER; false for other names.
bool queryRenderModePointer(const Context& ctx, GLenum pname, void** pointer);

}  // namespace glass::gl
