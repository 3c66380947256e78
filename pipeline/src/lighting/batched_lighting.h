// Per-vertex lighting of many vertices at a time, for the vertex fast path
// (vertex/vertex_batch.h; docs/pipeline.md, "The vertex fast path"). It evaluates the lighting
// equation of lighting_equation.cpp light by light over arrays of vertices (one array per
// component, so that the loops run over vertices and the compiler can use SIMD lanes for them),
// and computes once what is the same for every vertex: a directional light's direction and, for
// a viewer at infinity, its half vector; a spotlight's unit direction and cone. Every term takes
// the same float operations in the same order as evaluateLighting (lighting/lighting_math.h holds
// the steps both use), so the colours are the same bytes.
#pragma once

#include "core/simd_dispatch.h"
#include "lighting/lighting_state.h"

namespace glass::gl {

inline constexpr int kLightingBatch = 64;

// What the equation needs of each vertex, one row per component.
struct LightingInput {
  int count = 0;                        // vertices, at most kLightingBatch
  float point[3][kLightingBatch];       // V in eye coordinates, divided by w
  float normal[3][kLightingBatch];      // the eye-space normal n as the equation uses it
  // With GL_COLOR_MATERIAL: the vertices' current colours (4 rows), which replace the tracked
  // material parameters; nullptr to light with the stored materials alone.
  const float (*color)[kLightingBatch] = nullptr;
};

struct LitColorRows {
  float primary[4][kLightingBatch];    // c_pri, clamped to [0, 1]
  float secondary[4][kLightingBatch];  // c_sec (the specular sum, or 0), clamped
};

// Lights face `face` (kFrontMaterial or kBackMaterial) of every vertex; for the back face of
// two-sided lighting, reverseNormal lights it as if the normal pointed the other way.
void lightBatch(const LightingState& state, int face, bool reverseNormal, const LightingInput& in,
                LitColorRows& out);
// The same with the copy compiled for `target` (which must run here), for the tests.
void lightBatchWith(SimdTarget target, const LightingState& state, int face, bool reverseNormal,
                    const LightingInput& in, LitColorRows& out);

}  // namespace glass::gl
