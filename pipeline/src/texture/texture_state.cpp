#include "texture/texture_state.h"

namespace glass::gl {

TextureState::TextureState() {
  default1D.target = GL_TEXTURE_1D;
  default2D.target = GL_TEXTURE_2D;
  setDefaultTexGenPlanes(texGen);
}

const TextureObject* TextureState::activeTexture() const {
  const TextureObject* texture = enabled2D ? bound2D : enabled1D ? bound1D : nullptr;
  return texture != nullptr && texture->complete ? texture : nullptr;
}

}  // namespace glass::gl
