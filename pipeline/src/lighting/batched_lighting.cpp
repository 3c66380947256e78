// lightBatch (batched_lighting.h), compiled once per SIMD target (hwy/foreach_target.h
// re-includes this file per target, as for the fragment kernels): the loops over a batch's
// vertices are plain C++ that the compiler turns into vector code of each target's width.
//
// Equality between targets: every operation in the loops is one IEEE operation per lane
// (add, multiply, exact division and square root, compare and select); -ffp-contract=off keeps
// multiplies and adds apart on targets with FMA, and the power of the specular term is the same
// library call on every target. So every target gives the same bits, and image_simd_targets
// compares them on every image test.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "lighting/batched_lighting.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "core/simd_dispatch.h"
#include "lighting/batched_lighting.h"
#include "lighting/color_material.h"
#include "lighting/lighting_math.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace {

constexpr int K = kLightingBatch;

using Rows3 = float[3][K];

// The material colours of every vertex: the stored material, with the parameters colour
// material tracks taken from each vertex's colour (the value applyColorMaterial would have
// stored when that vertex's glColor came).
struct MaterialRows {
  float ambient[4][K], diffuse[4][K], specular[4][K], emission[4][K];
};

void fillMaterialRows(const LightingState& state, int face, const float (*color)[K], int n,
                      MaterialRows& m) {
  const Material& base = state.materials[face];
  const float* stored[4] = {base.ambient, base.diffuse, base.specular, base.emission};
  float(*rows[4])[K] = {m.ambient, m.diffuse, m.specular, m.emission};
  static constexpr GLenum kNames[4] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
  for (int p = 0; p < 4; ++p) {
    const bool tracked = color != nullptr && tracksCurrentColor(state.colorMaterial, face, kNames[p]);
    for (int c = 0; c < 4; ++c) {
      float* row = rows[p][c];
      if (tracked) {
        for (int i = 0; i < n; ++i) row[i] = color[c][i];
      } else {
        for (int i = 0; i < n; ++i) row[i] = stored[p][c];
      }
    }
  }
}

// normalize3 of every vertex's vector (x, y, z): the same operations, with a select for the
// zero vectors normalize3 leaves alone (times 1 leaves every value as it is).
void normalizeRows(float* x, float* y, float* z, int n) {
  for (int i = 0; i < n; ++i) {
    const float lengthSquared = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const float reciprocal = 1.0f / std::sqrt(lengthSquared);  // computed always, used if > 0
    const float inverseLength = lengthSquared > 0.0f ? reciprocal : 1.0f;
    x[i] *= inverseLength;
    y[i] *= inverseLength;
    z[i] *= inverseLength;
  }
}

// VP_i and att_i of a light at every vertex (lightGeometry in lighting_equation.cpp).
void lightGeometryRows(const LightSource& light, const LightingInput& in, Rows3& toLight,
                       float* attenuation) {
  const int n = in.count;
  const float* p = light.position;
  if (p[3] == 0.0f) {
    float direction[3];
    lighting_math::directionalToLight(light, direction);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < n; ++i) toLight[c][i] = direction[c];
    for (int i = 0; i < n; ++i) attenuation[i] = 1.0f;
    return;
  }
  const float inverseW = 1.0f / p[3];
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) toLight[c][i] = p[c] * inverseW - in.point[c][i];
  for (int i = 0; i < n; ++i) {
    const float distanceSquared =
        toLight[0][i] * toLight[0][i] + toLight[1][i] * toLight[1][i] + toLight[2][i] * toLight[2][i];
    const float distance = std::sqrt(distanceSquared);
    attenuation[i] = 1.0f / (light.constantAttenuation + light.linearAttenuation * distance +
                             light.quadraticAttenuation * distanceSquared);
  }
  normalizeRows(toLight[0], toLight[1], toLight[2], n);
}

// lightingPower(base[i], exponent) for every i where wanted[i]; the other entries of power are
// left as they are. A whole exponent is squared in double over the whole batch at once, the
// same multiplications in the same order as lightingPower's loop makes for one base, so every
// lane gets lightingPower's bits; other exponents call lightingPower lane by lane.
void powerRows(const float* base, float exponent, const bool* wanted, int n, float* power) {
  if (!lighting_math::isWholeLightingExponent(exponent)) {
    for (int i = 0; i < n; ++i)
      if (wanted[i]) power[i] = lighting_math::lightingPower(base[i], exponent);
    return;
  }
  double result[K], square[K];
  for (int i = 0; i < n; ++i) {
    result[i] = 1.0;
    square[i] = base[i];
  }
  for (unsigned e = static_cast<unsigned>(exponent); e != 0; e >>= 1) {
    if (e & 1u)
      for (int i = 0; i < n; ++i) result[i] *= square[i];
    if (e > 1u)
      for (int i = 0; i < n; ++i) square[i] *= square[i];
  }
  for (int i = 0; i < n; ++i)
    if (wanted[i]) power[i] = static_cast<float>(result[i]);
}

// spot_i at every vertex; 1 without a cone (spotFactor's steps, the power over the batch).
void spotRows(const LightSource& light, const Rows3& toLight, int n, float* spot) {
  if (light.spotCutoff == 180.0f) {
    for (int i = 0; i < n; ++i) spot[i] = 1.0f;
    return;
  }
  float direction[3];
  lighting_math::unitSpotDirection(light, direction);
  const float cosCutoff = lighting_math::spotCosCutoff(light);
  float base[K];
  bool inside[K];
  for (int i = 0; i < n; ++i) {
    const float cosine = -(toLight[0][i] * direction[0] + toLight[1][i] * direction[1] +
                           toLight[2][i] * direction[2]);
    inside[i] = !(cosine < cosCutoff);
    base[i] = cosine > 0.0f ? cosine : 0.0f;
    spot[i] = 0.0f;
  }
  powerRows(base, light.spotExponent, inside, n, spot);
}

}  // namespace

void LightBatch(const LightingState& state, int face, bool reverseNormal, const LightingInput& in,
                LitColorRows& out) {
  const int n = in.count;
  MaterialRows m;
  fillMaterialRows(state, face, in.color, n, m);
  const float shininess = state.materials[face].shininess;

  Rows3 normal;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) normal[c][i] = reverseNormal ? -in.normal[c][i] : in.normal[c][i];

  // e_cm + a_cm * a_cs.
  float sum[3][K], specularSum[3][K];
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) {
      sum[c][i] = m.emission[c][i] + m.ambient[c][i] * state.model.ambient[c];
      specularSum[c][i] = 0.0f;
    }

  // VP_e: towards the eye at the origin (local viewer), else +z everywhere.
  const bool localViewer = state.model.localViewer;
  Rows3 toEye;
  if (localViewer) {
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < n; ++i) toEye[c][i] = -in.point[c][i];
    normalizeRows(toEye[0], toEye[1], toEye[2], n);
  }

  for (const LightSource& light : state.lights) {
    if (!light.enabled) continue;
    Rows3 toLight;
    float attenuation[K], spot[K], scale[K], nDotL[K], specular[K];
    lightGeometryRows(light, in, toLight, attenuation);
    spotRows(light, toLight, n, spot);
    for (int i = 0; i < n; ++i) {
      scale[i] = attenuation[i] * spot[i];
      nDotL[i] = normal[0][i] * toLight[0][i] + normal[1][i] * toLight[1][i] +
                 normal[2][i] * toLight[2][i];
    }

    // The half vector: one for all vertices when both VP_i and VP_e are the same everywhere.
    const bool constantHalf = light.position[3] == 0.0f && !localViewer;
    float half[3][K];
    if (constantHalf) {
      float h[3] = {toLight[0][0] + 0.0f, toLight[1][0] + 0.0f, toLight[2][0] + 1.0f};
      lighting_math::normalize3(h);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) half[c][i] = h[c];
    } else {
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
          half[c][i] = toLight[c][i] + (localViewer ? toEye[c][i] : (c == 2 ? 1.0f : 0.0f));
      normalizeRows(half[0], half[1], half[2], n);
    }
    // f_i (n . h_i)^s only where the light reaches the front of the surface (specularFactor's
    // steps, the power over the batch).
    float nDotHBase[K];
    bool facing[K];
    for (int i = 0; i < n; ++i) {
      const float nDotH =
          normal[0][i] * half[0][i] + normal[1][i] * half[1][i] + normal[2][i] * half[2][i];
      nDotHBase[i] = nDotH > 0.0f ? nDotH : 0.0f;
      facing[i] = scale[i] != 0.0f && nDotL[i] > 0.0f;
      specular[i] = 0.0f;
    }
    powerRows(nDotHBase, shininess, facing, n, specular);
    float diffuse[K];
    for (int i = 0; i < n; ++i) diffuse[i] = nDotL[i] > 0.0f ? nDotL[i] : 0.0f;
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < n; ++i) {
        const lighting_math::LightChannelTerms terms = lighting_math::lightChannelTerms(
            scale[i], diffuse[i], specular[i], m.ambient[c][i], m.diffuse[c][i], m.specular[c][i],
            light.ambient[c], light.diffuse[c], light.specular[c]);
        // Where the light does not reach (scale 0), evaluateLighting skips it: adding -0 leaves
        // every sum as it is (even -0 and NaN), so the sums stay.
        const bool reached = scale[i] != 0.0f;
        sum[c][i] += reached ? terms.lit : -0.0f;
        specularSum[c][i] += reached ? terms.specular : -0.0f;
      }
  }

  const bool separate = state.model.separateSpecular;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i)
      lighting_math::finishChannel(separate, sum[c][i], specularSum[c][i], out.primary[c][i],
                                   out.secondary[c][i]);
  for (int i = 0; i < n; ++i) {
    out.primary[3][i] = lighting_math::clamp01(m.diffuse[3][i]);
    out.secondary[3][i] = 0.0f;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(LightBatch))> kLightBatch =
    GLASS_SIMD_FUNCTIONS(LightBatch);

void lightBatch(const LightingState& state, int face, bool reverseNormal, const LightingInput& in,
                LitColorRows& out) {
  chosenSimdFunction(kLightBatch)(state, face, reverseNormal, in, out);
}

void lightBatchWith(SimdTarget target, const LightingState& state, int face, bool reverseNormal,
                    const LightingInput& in, LitColorRows& out) {
  kLightBatch[static_cast<int>(target)](state, face, reverseNormal, in, out);
}

}  // namespace glass::gl
#endif  // HWY_ONCE
