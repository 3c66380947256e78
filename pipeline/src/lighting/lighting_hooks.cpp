// The lighting stage as the pipeline sees it: the capabilities and queries of lighting state,
// per-vertex lighting (Gouraud: the colours are interpolated), per-fragment lighting (the
// GL_WIN_phong_shading extension: the normal and position are interpolated and the equation is
// evaluated at every fragment) and colour material tracking. The equation itself is in
// lighting_equation.cpp.
#include "lighting/lighting_hooks.h"

#include <cmath>

#include "core/context.h"
#include "core/state_value.h"
#include "lighting/color_material.h"
#include "lighting/lighting_equation.h"
#include "primitive/queued_drawing.h"
#include "vertex/gathered_vertices.h"

namespace glass::gl {

namespace {

// GL_LIGHTi as an index 0..7, or -1.
int lightIndex(GLenum cap) {
  if (cap < GL_LIGHT0 || cap >= GL_LIGHT0 + kMaxLights) return -1;
  return static_cast<int>(cap - GL_LIGHT0);
}

void copy4(const float in[4], float out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = in[i];
}

}  // namespace

bool setLightingCapability(Context& ctx, GLenum cap, bool enabled) {
  LightingState& l = ctx.lighting;
  if (cap == GL_LIGHTING) {
    l.enabled = enabled;
    return true;
  }
  if (cap == GL_COLOR_MATERIAL) {
    l.colorMaterial.enabled = enabled;
    // From the moment it is enabled, the tracked parameters equal the current colour.
    if (enabled) applyColorMaterial(l, ctx.current.color);
    return true;
  }
  const int i = lightIndex(cap);
  if (i < 0) return false;
  l.lights[i].enabled = enabled;
  return true;
}

bool getLightingCapability(const Context& ctx, GLenum cap, bool& enabled) {
  const LightingState& l = ctx.lighting;
  if (cap == GL_LIGHTING) {
    enabled = l.enabled;
    return true;
  }
  if (cap == GL_COLOR_MATERIAL) {
    enabled = l.colorMaterial.enabled;
    return true;
  }
  const int i = lightIndex(cap);
  if (i < 0) return false;
  enabled = l.lights[i].enabled;
  return true;
}

bool queryLightingState(const Context& ctx, GLenum pname, StateValue& value) {
  const LightingState& l = ctx.lighting;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: value.setColors(l.model.ambient, 4); return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: value.setBooleans({l.model.localViewer}); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: value.setBooleans({l.model.twoSide}); return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      value.setIntegers({double(l.model.separateSpecular ? GL_SEPARATE_SPECULAR_COLOR
                                                         : GL_SINGLE_COLOR)});
      return true;
    case GL_COLOR_MATERIAL_FACE: value.setIntegers({double(l.colorMaterial.face)}); return true;
    case GL_COLOR_MATERIAL_PARAMETER:
      value.setIntegers({double(l.colorMaterial.mode)});
      return true;
    case GL_MAX_LIGHTS: value.setIntegers({double(kMaxLights)}); return true;
    default: return false;
  }
}

bool lightingEnabled(const Context& ctx) { return ctx.lighting.enabled; }
bool twoSidedLighting(const Context& ctx) {
  return ctx.lighting.enabled && ctx.lighting.model.twoSide;
}
bool separateSpecularColor(const Context& ctx) {
  return ctx.lighting.enabled && ctx.lighting.model.separateSpecular;
}

void lightVertex(const Context& ctx, const float eyePosition[4], const float eyeNormal[3],
                 LitVertexColors& out) {
  const LightingState& l = ctx.lighting;
  float point[3];
  eyePointFromHomogeneous(eyePosition, point);
  evaluateLighting(l, l.materials[kFrontMaterial], point, eyeNormal, out.front,
                   out.frontSecondary);
  if (l.model.twoSide) {
    // Back faces are lit with the back material as if the normal pointed the other way
    // (spec 2.13.1, "two-sided lighting").
    const float reversed[3] = {-eyeNormal[0], -eyeNormal[1], -eyeNormal[2]};
    evaluateLighting(l, l.materials[kBackMaterial], point, reversed, out.back, out.backSecondary);
  } else {
    copy4(out.front, out.back);
    copy4(out.frontSecondary, out.backSecondary);
  }
}

void lightFragment(const Context& ctx, const float eyePosition[3], const float eyeNormal[3],
                   bool frontFacing, float color[4], float secondary[4]) {
  const LightingState& l = ctx.lighting;
  // Interpolation shortens the normal between vertices; lighting needs it unit length again.
  float normal[3] = {eyeNormal[0], eyeNormal[1], eyeNormal[2]};
  const float lengthSquared = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
  if (lengthSquared > 0.0f) {
    const float inverseLength = 1.0f / std::sqrt(lengthSquared);
    for (float& c : normal) c *= inverseLength;
  }
  const bool back = l.model.twoSide && !frontFacing;
  if (back) {
    for (float& c : normal) c = -c;
  }
  const int face = back ? kBackMaterial : kFrontMaterial;
  // With colour material, the fragment's own interpolated colour is the tracked parameter.
  if (l.colorMaterial.enabled) {
    const Material material = materialWithColor(l, face, color);
    evaluateLighting(l, material, eyePosition, normal, color, secondary);
  } else {
    evaluateLighting(l, l.materials[face], eyePosition, normal, color, secondary);
  }
}

void onCurrentColorChanged(Context& ctx) {
  if (!ctx.lighting.colorMaterial.enabled) return;
  if (deferColorMaterial(ctx)) return;  // a gathering glBegin/glEnd applies it at glEnd
  beforeColorMaterialChange(ctx);  // queued per-fragment lighting may be reading the material
  applyColorMaterial(ctx.lighting, ctx.current.color);
}

}  // namespace glass::gl
