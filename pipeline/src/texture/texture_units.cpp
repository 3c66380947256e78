#include "texture/texture_units.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryTextureUnitState(const Context& ctx, GLenum pname, StateValue& v) {
  switch (pname) {
    case GL_ACTIVE_TEXTURE:
      v.setIntegers({double(GL_TEXTURE0 + ctx.texture.activeUnit)});
      return true;
    case GL_CLIENT_ACTIVE_TEXTURE:
      v.setIntegers({double(GL_TEXTURE0 + ctx.arrays.clientActiveUnit)});
      return true;
    case GL_MAX_TEXTURE_UNITS: v.setIntegers({double(kTextureUnitCount)}); return true;
    default: return false;
  }
}

}  // namespace glass::gl
