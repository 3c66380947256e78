// Texturing state (OpenGL 1.5 specification, section 3.8; tables 6.15 to 6.19): the texture
// objects, shared by all texture units, and per unit (texture_units.h) the enables, the bindings,
// the texture environment and texture coordinate generation. Member initialisers are the GL
// defaults. The texture matrix stacks belong to TransformState, the current texture coordinates
// to CurrentState, the texture coordinate arrays to ArrayState.
#pragma once

#include <GL/gl.h>

#include <memory>
#include <vector>

#include "texture/bump_map_state.h"
#include "texture/texgen.h"
#include "texture/texture_environment.h"
#include "texture/texture_names.h"
#include "texture/texture_object.h"
#include "texture/texture_units.h"

namespace glass::gl {

// The state of one texture unit (spec 2.7, 3.8.17).
struct TextureUnit {
  bool enabled1D = false;  // glEnable(GL_TEXTURE_1D)
  bool enabled2D = false;  // glEnable(GL_TEXTURE_2D)
  bool enabled3D = false;  // glEnable(GL_TEXTURE_3D)
  bool enabledCube = false;  // glEnable(GL_TEXTURE_CUBE_MAP)
  TextureObject* bound1D = nullptr;  // never null once TextureState is constructed
  TextureObject* bound2D = nullptr;
  TextureObject* bound3D = nullptr;
  TextureObject* boundCube = nullptr;
  TextureEnvironment env;             // glTexEnv (section 3.8.13)
  TexGenCoordinate texGen[4];         // glTexGen for s, t, r, q (section 2.11.4)

  bool anyTargetEnabled() const { return enabled1D || enabled2D || enabled3D || enabledCube; }
  // The texture the unit samples: the cube map if GL_TEXTURE_CUBE_MAP is enabled, else the 3D,
  // 2D or 1D texture, the first of them whose target is enabled; null when none is
  // enabled or the texture of the target that takes precedence is incomplete (spec 3.8.15: the
  // unit is then off).
  const TextureObject* activeTexture() const;
};

struct TextureState {
  TextureState();
  TextureState(const TextureState&) = delete;
  TextureState& operator=(const TextureState&) = delete;

  // The texture objects named 0, one per target (spec 3.8.12: "the default texture"), shared by
  // the units.
  TextureObject default1D;
  TextureObject default2D;
  TextureObject default3D;
  TextureObject defaultCube;
  // Named objects (glBindTexture creates them), shared with the contexts this one shares them with.
  std::shared_ptr<TextureNames> names = std::make_shared<TextureNames>();

  // Proxy textures (spec 3.8.11): only the size and format of each level are kept.
  TextureImage proxy1D[kMaxTextureLevels];
  TextureImage proxy2D[kMaxTextureLevels];
  TextureImage proxy3D[kMaxTextureLevels];
  TextureImage proxyCube[kMaxTextureLevels];

  TextureUnit units[kTextureUnitCount];
  int activeUnit = 0;  // glActiveTexture: GL_TEXTURE0 + activeUnit

  // The bump-mapping extension (docs/texturing.md).
  BumpMapState bumpMap;

  TextureUnit& unit() { return units[activeUnit]; }
  const TextureUnit& unit() const { return units[activeUnit]; }

  // Keeps every named texture the units are bound to alive (texture_names.h) and lets go of the
  // others; called after every change of bindings.
  void holdBindings();

 private:
  std::vector<std::shared_ptr<TextureObject>> heldBindings_;
};

}  // namespace glass::gl
