// Texturing state (OpenGL 1.5 specification, section 3.8; tables 6.15 to 6.18): the texture
// objects and their bindings, the enables, the texture environment and texture coordinate
// generation. glass has one texture unit (GL 1.1 texturing, without GL_ARB_multitexture).
// Member initialisers are the GL defaults. The texture matrix stack belongs to TransformState.
#pragma once

#include <GL/gl.h>

#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "texture/bump_map_state.h"
#include "texture/texgen.h"
#include "texture/texture_object.h"

namespace glass::gl {

struct TextureState {
  TextureState();
  TextureState(const TextureState&) = delete;
  TextureState& operator=(const TextureState&) = delete;

  bool enabled1D = false;  // glEnable(GL_TEXTURE_1D)
  bool enabled2D = false;  // glEnable(GL_TEXTURE_2D)

  // The texture objects named 0, one per target (spec 3.8.12: "the default texture").
  TextureObject default1D;
  TextureObject default2D;
  // Named objects (glBindTexture creates them); pointers stay valid until glDeleteTextures.
  std::unordered_map<GLuint, std::unique_ptr<TextureObject>> objects;
  // Names returned by glGenTextures and not yet bound: in use, but not yet textures (glIsTexture
  // is false for them, spec 3.8.12).
  std::unordered_set<GLuint> reservedNames;
  GLuint nextName = 1;  // where glGenTextures starts looking

  TextureObject* bound1D = &default1D;
  TextureObject* bound2D = &default2D;

  // Proxy textures (spec 3.8.11): only the size and format of each level are kept.
  TextureImage proxy1D[kMaxTextureLevels];
  TextureImage proxy2D[kMaxTextureLevels];

  // glTexEnv (section 3.8.13).
  GLenum envMode = GL_MODULATE;
  float envColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};

  // glTexGen for s, t, r, q (section 2.11.4).
  TexGenCoordinate texGen[4];

  // The bump-mapping extension (docs/texturing.md).
  BumpMapState bumpMap;

  // The texture a fragment is textured with: the 2D texture if GL_TEXTURE_2D is enabled, else
  // the 1D texture if GL_TEXTURE_1D is; null when neither is enabled or the texture of the
  // highest enabled dimension is incomplete (spec 3.8.15: texturing is then off).
  const TextureObject* activeTexture() const;
};

}  // namespace glass::gl
