// Placeholder lighting hooks: replaced by the lighting stage. Lighting is off; GL_LIGHTING and
// the other lighting capabilities are not yet recognised.
#include "lighting/lighting_hooks.h"

#include "core/context.h"

namespace glass::gl {

bool setLightingCapability(Context&, GLenum, bool) { return false; }
bool getLightingCapability(const Context&, GLenum, bool&) { return false; }
bool queryLightingState(const Context&, GLenum, StateValue&) { return false; }
bool lightingEnabled(const Context&) { return false; }
bool twoSidedLighting(const Context&) { return false; }
bool separateSpecularColor(const Context&) { return false; }

void lightVertex(const Context& ctx, const float*, const float*, LitVertexColors& out) {
  for (int i = 0; i < 4; ++i) {
    out.front[i] = out.back[i] = ctx.current.color[i];
    out.frontSecondary[i] = out.backSecondary[i] = 0.0f;
  }
}

void lightFragment(const Context&, const float*, const float*, bool, float*, float* secondary) {
  for (int i = 0; i < 4; ++i) secondary[i] = 0.0f;
}

void onCurrentColorChanged(Context&) {}

}  // namespace glass::gl
