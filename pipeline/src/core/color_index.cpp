#include "core/color_index.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryColorIndexState(const Context& ctx, GLenum pname, StateValue& v) {
  switch (pname) {
    case GL_CURRENT_INDEX: v.setFloats({ctx.current.index}); return true;
    case GL_INDEX_CLEAR_VALUE: v.setFloats({ctx.fragment.clearIndex}); return true;
    // The mask as a signed integer, as Mesa returns it (all ones reads as -1).
    case GL_INDEX_WRITEMASK:
      v.setIntegers({double(static_cast<GLint>(ctx.fragment.indexMask))});
      return true;
    case GL_INDEX_ARRAY_TYPE: v.setIntegers({double(ctx.arrays.index.type)}); return true;
    case GL_INDEX_ARRAY_STRIDE: v.setIntegers({double(ctx.arrays.index.stride)}); return true;
    default: return false;
  }
}

}  // namespace glass::gl
