// The interface between the pipeline and the lighting stage (spec 2.13). The pipeline calls these;
// the lighting stage implements them in lighting/ (lighting_hooks.cpp).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// The colours of a lit vertex. back* are used for back-facing primitives when two-sided lighting
// is on; the secondary colours hold the specular term with GL_SEPARATE_SPECULAR_COLOR and are
// zero otherwise (alpha 0 in both cases).
struct LitVertexColors {
  float front[4], back[4], frontSecondary[4], backSecondary[4];
};

// glEnable/glDisable of the lighting stage's capabilities (GL_LIGHTING, GL_LIGHTi,
// GL_COLOR_MATERIAL). Returns false when cap is not one of them.
bool setLightingCapability(Context& ctx, GLenum cap, bool enabled);
// glIsEnabled of the same capabilities. Returns false when cap is not one of them.
bool getLightingCapability(const Context& ctx, GLenum cap, bool& enabled);
// glGet of the lighting stage's state (GL_LIGHT_MODEL_AMBIENT, GL_SHADE_MODEL is not here, ...).
// Returns false when pname is not lighting state.
bool queryLightingState(const Context& ctx, GLenum pname, StateValue& value);

bool lightingEnabled(const Context& ctx);           // GL_LIGHTING
bool twoSidedLighting(const Context& ctx);          // lighting on and GL_LIGHT_MODEL_TWO_SIDE
bool separateSpecularColor(const Context& ctx);     // lighting on, GL_SEPARATE_SPECULAR_COLOR

// Per vertex, when GL_LIGHTING is on and the shade model is not GL_PHONG_WIN. eyeNormal is the
// normal transformed by the inverse transpose of the modelview matrix and normalized or rescaled
// as GL_NORMALIZE / GL_RESCALE_NORMAL ask.
void lightVertex(const Context& ctx, const float eyePosition[4], const float eyeNormal[3],
                 LitVertexColors& out);

// Per fragment, for glShadeModel(GL_PHONG_WIN) with lighting on: eyePosition and eyeNormal are the
// interpolated varyings (the normal is not renormalized). color holds the interpolated current
// colour on entry (for colour material); the lit primary and secondary colours on return.
void lightFragment(const Context& ctx, const float eyePosition[3], const float eyeNormal[3],
                   bool frontFacing, float color[4], float secondary[4]);

// Called by every glColor* after the current colour changed (glColorMaterial tracking). Inside a
// gathering glBegin/glEnd the tracked parameters are updated once, at glEnd
// (vertex/gathered_vertices.h, deferColorMaterial).
void onCurrentColorChanged(Context& ctx);

}  // namespace glass::gl
