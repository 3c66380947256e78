// glColorMaterial (spec 2.13.3): while GL_COLOR_MATERIAL is enabled, the material parameters it
// names track the current colour.
#pragma once

#include <GL/gl.h>

#include "lighting/lighting_state.h"

namespace glass::gl {

// Which faces a glColorMaterial/glMaterial face argument names: bit 0 front, bit 1 back.
unsigned materialFaceMask(GLenum face);

// Whether the colour material setting makes parameter `pname` of face `faceIndex`
// (kFrontMaterial or kBackMaterial) follow the current colour.
bool tracksCurrentColor(const ColorMaterialState& cm, int faceIndex, GLenum pname);

// Copies `color` into every material parameter colour material names (nothing when disabled).
void applyColorMaterial(LightingState& lighting, const float color[4]);

// The material of one face as lighting sees it when the colour of the point is `color`: the
// stored material, with the tracked parameters replaced by `color`. Per-fragment lighting uses
// it with the interpolated colour.
Material materialWithColor(const LightingState& lighting, int faceIndex, const float color[4]);

}  // namespace glass::gl
