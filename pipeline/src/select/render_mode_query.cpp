#include "select/render_mode_query.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryRenderModeState(const Context& ctx, GLenum pname, StateValue& v) {
  const RenderModeState& r = ctx.renderMode;
  switch (pname) {
    case GL_RENDER_MODE: v.setIntegers({double(r.mode)}); return true;
    case GL_NAME_STACK_DEPTH: v.setIntegers({double(r.selection.nameStackDepth)}); return true;
    case GL_MAX_NAME_STACK_DEPTH: v.setIntegers({kMaxNameStackDepth}); return true;
    case GL_SELECTION_BUFFER_SIZE: v.setIntegers({double(r.selection.bufferSize)}); return true;
    case GL_FEEDBACK_BUFFER_SIZE: v.setIntegers({double(r.feedback.bufferSize)}); return true;
    case GL_FEEDBACK_BUFFER_TYPE: v.setIntegers({double(r.feedback.type)}); return true;
    default: return false;
  }
}

bool queryRenderModePointer(const Context& ctx, GLenum pname, void** pointer) {
  switch (pname) {
    case GL_SELECTION_BUFFER_POINTER: *pointer = ctx.renderMode.selection.buffer; return true;
    case GL_FEEDBACK_BUFFER_POINTER: *pointer = ctx.renderMode.feedback.buffer; return true;
    default: return false;
  }
}

}  // namespace glass::gl
