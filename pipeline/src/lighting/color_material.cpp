#include "lighting/color_material.h"

namespace glass::gl {

namespace {

void copy4(const float in[4], float out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = in[i];
}

// Sets the parameters `mode` names in one material.
void setTracked(Material& m, GLenum mode, const float color[4]) {
  switch (mode) {
    case GL_EMISSION: copy4(color, m.emission); break;
    case GL_AMBIENT: copy4(color, m.ambient); break;
    case GL_DIFFUSE: copy4(color, m.diffuse); break;
    case GL_SPECULAR: copy4(color, m.specular); break;
    case GL_AMBIENT_AND_DIFFUSE:
      copy4(color, m.ambient);
      copy4(color, m.diffuse);
      break;
    default: break;
  }
}

}  // namespace

unsigned materialFaceMask(GLenum face) {
  switch (face) {
    case GL_FRONT: return 1u;
    case GL_BACK: return 2u;
    case GL_FRONT_AND_BACK: return 3u;
    default: return 0u;
  }
}

bool tracksCurrentColor(const ColorMaterialState& cm, int faceIndex, GLenum pname) {
  if (!cm.enabled || !(materialFaceMask(cm.face) & (1u << faceIndex))) return false;
  if (cm.mode == pname) return true;
  return cm.mode == GL_AMBIENT_AND_DIFFUSE && (pname == GL_AMBIENT || pname == GL_DIFFUSE);
}

void applyColorMaterial(LightingState& lighting, const float color[4]) {
  const ColorMaterialState& cm = lighting.colorMaterial;
  if (!cm.enabled) return;
  const unsigned faces = materialFaceMask(cm.face);
  for (int f = 0; f < 2; ++f) {
    if (faces & (1u << f)) setTracked(lighting.materials[f], cm.mode, color);
  }
}

Material materialWithColor(const LightingState& lighting, int faceIndex, const float color[4]) {
  Material m = lighting.materials[faceIndex];
  const ColorMaterialState& cm = lighting.colorMaterial;
  if (cm.enabled && (materialFaceMask(cm.face) & (1u << faceIndex))) setTracked(m, cm.mode, color);
  return m;
}

}  // namespace glass::gl
