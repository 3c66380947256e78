#include "vertex/secondary_attributes.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool querySecondaryAttributeState(const Context& ctx, GLenum pname, StateValue& v) {
  const ArrayState& a = ctx.arrays;
  switch (pname) {
    case GL_CURRENT_FOG_COORDINATE: v.setFloats({ctx.current.fogCoord}); return true;
    case GL_CURRENT_SECONDARY_COLOR: v.setColors(ctx.current.secondaryColor, 4); return true;
    case GL_FOG_COORDINATE_ARRAY_TYPE: v.setIntegers({double(a.fogCoord.type)}); return true;
    case GL_FOG_COORDINATE_ARRAY_STRIDE: v.setIntegers({double(a.fogCoord.stride)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_SIZE: v.setIntegers({double(a.secondaryColor.size)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_TYPE: v.setIntegers({double(a.secondaryColor.type)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_STRIDE:
      v.setIntegers({double(a.secondaryColor.stride)});
      return true;
    default: return false;
  }
}

}  // namespace glass::gl
