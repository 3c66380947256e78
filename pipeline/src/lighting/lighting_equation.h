// The OpenGL 1.x lighting equation (OpenGL 1.5 specification, section 2.13.1), free of any GL
// context: it reads only a LightingState, so unit tests call it directly and both per-vertex
// lighting (Gouraud) and per-fragment lighting (the GL_WIN_phong_shading extension) share it.
// docs/lighting.md walks through it term by term.
#pragma once

#include "lighting/lighting_state.h"

namespace glass::gl {

// Lights one face of a surface point.
//   eyePoint  the point V in eye coordinates (x, y, z), already divided by w
//   normal    the eye-space normal n as given: the equation uses it as it is (the pipeline
//             normalizes it first only when GL_NORMALIZE or GL_RESCALE_NORMAL asks for it).
//             For a back face the caller passes the reversed normal.
//   material  the front or the back material
// Writes the primary colour c_pri (RGB lit, alpha = the material's diffuse alpha) and the
// secondary colour c_sec (the specular sum when GL_SEPARATE_SPECULAR_COLOR is set, else zero;
// its alpha is always 0), each clamped to [0, 1].
// trace, when given, receives each term's value (GLASS_TRACE_VERTEX prints them).
struct LightingTerms {
  float base[3] = {};  // e_cm + a_cm * a_cs
  struct Light {
    int index = 0;                     // GL_LIGHT0 + index
    float attenuation = 0.0f, spot = 0.0f;
    float nDotL = 0.0f;                // n . VP_i, before clamping
    float specularFactor = 0.0f;       // f_i (n . h_i)^s_rm
    float ambient[3] = {}, diffuse[3] = {}, specular[3] = {};  // each times att_i spot_i
  };
  Light lights[kMaxLights];
  int lightCount = 0;                  // the enabled lights, in order
};
void evaluateLighting(const LightingState& state, const Material& material,
                      const float eyePoint[3], const float normal[3], float primary[4],
                      float secondary[4], LightingTerms* trace = nullptr);

// The point (x/w, y/w, z/w) of a homogeneous eye-space position. A position with w = 0 (only
// reachable through glVertex4 with w = 0) is taken as the point (x, y, z).
void eyePointFromHomogeneous(const float eyePosition[4], float point[3]);

// One coordinate of that point: c itself when w is 1 or 0, else c times the reciprocal of w.
// Written as a selection, so that a loop over vertices (processBatch) becomes vector code; the
// reciprocal of a w of 0 is computed there and not chosen.
inline float eyeCoordinateFromHomogeneous(float c, float w) {
  const float scaled = c * (1.0f / w);
  return w == 1.0f || w == 0.0f ? c : scaled;
}

}  // namespace glass::gl
