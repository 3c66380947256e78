#include "texture/texture_state.h"

namespace glass::gl {

TextureState::TextureState() {
  default1D.target = GL_TEXTURE_1D;
  default2D.target = GL_TEXTURE_2D;
  default3D.target = GL_TEXTURE_3D;
  defaultCube.target = GL_TEXTURE_CUBE_MAP;
  for (TextureUnit& u : units) {
    u.bound1D = &default1D;
    u.bound2D = &default2D;
    u.bound3D = &default3D;
    u.boundCube = &defaultCube;
    setDefaultTexGenPlanes(u.texGen);
  }
}

void TextureState::holdBindings() {
  std::vector<std::shared_ptr<TextureObject>> held;
  held.reserve(static_cast<size_t>(kTextureUnitCount) * 4);
  for (const TextureUnit& u : units) {
    for (TextureObject* bound : {u.bound1D, u.bound2D, u.bound3D, u.boundCube}) {
      if (bound->name != 0) held.push_back(bound->shared_from_this());
    }
  }
  heldBindings_ = std::move(held);
}

const TextureObject* TextureUnit::activeTexture() const {
  const TextureObject* texture = enabledCube ? boundCube
                                : enabled3D   ? bound3D
                                : enabled2D   ? bound2D
                                : enabled1D   ? bound1D
                                              : nullptr;
  return texture != nullptr && texture->complete ? texture : nullptr;
}

}  // namespace glass::gl
