// State of the bump-mapping extension GL_GLASS_bump_map (docs/texturing.md): a height map, held
// in an ordinary 2D texture object, perturbs the interpolated normal before per-fragment lighting
// (glShadeModel(GL_PHONG_WIN)), as Blinn's bump mapping does.
//   glEnable(GL_BUMP_MAP_GLASS)
//   glTexEnvi(GL_BUMP_MAP_GLASS, GL_BUMP_MAP_TEXTURE_GLASS, heightMapTextureName)
//   glTexEnvf(GL_BUMP_MAP_GLASS, GL_BUMP_SCALE_GLASS, heightOfTexelValueOne)
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct BumpMapState {
  bool enabled = false;  // glEnable(GL_BUMP_MAP_GLASS)
  GLuint texture = 0;    // the name of the 2D texture object holding the height map
  // The height, in eye-space units, of a height-map value of 1 (the map's red or luminance).
  float scale = 1.0f;
};

}  // namespace glass::gl
