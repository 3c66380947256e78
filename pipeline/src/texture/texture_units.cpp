#include "texture/texture_units.h"

#include "core/state_value.h"

namespace glass::gl {

bool queryTextureUnitState(const Context&, GLenum pname, StateValue& v) {
  switch (pname) {
    case GL_ACTIVE_TEXTURE:
    case GL_CLIENT_ACTIVE_TEXTURE: v.setIntegers({double(GL_TEXTURE0)}); return true;
    default: return false;
  }
}

}  // namespace glass::gl
