// The small vector steps of the lighting equation (lighting_equation.cpp), shared by the
// equation for one point and the batched lighting of many vertices (batched_lighting.cpp), so
// that both evaluate every term with the same float operations in the same order and give the
// same bytes.
#pragma once

#include <cmath>
#include <numbers>

#include "lighting/lighting_state.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::lighting_math {

inline float dot3(const float a[3], const float b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Scales v to unit length; a zero vector stays zero (no direction to give it).
inline void normalize3(float v[3]) {
  const float lengthSquared = dot3(v, v);
  if (lengthSquared > 0.0f) {
    const float inverseLength = 1.0f / std::sqrt(lengthSquared);
    v[0] *= inverseLength;
    v[1] *= inverseLength;
    v[2] *= inverseLength;
  }
}

inline float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

// The unit vector VP_i towards a directional light (position w = 0): the same at every point.
inline void directionalToLight(const LightSource& light, float toLight[3]) {
  toLight[0] = light.position[0];
  toLight[1] = light.position[1];
  toLight[2] = light.position[2];
  normalize3(toLight);
}

// cos(c) of a spotlight's cutoff angle c, in degrees.
inline float spotCosCutoff(const LightSource& light) {
  const double cutoffRadians = static_cast<double>(light.spotCutoff) * std::numbers::pi / 180.0;
  return static_cast<float>(portable::cos(cutoffRadians));
}

// The spotlight's direction s_d as a unit vector.
inline void unitSpotDirection(const LightSource& light, float direction[3]) {
  direction[0] = light.spotDirection[0];
  direction[1] = light.spotDirection[1];
  direction[2] = light.spotDirection[2];
  normalize3(direction);
}

// base^exponent for the lighting's exponents (shininess and spot exponent, 0 to 128 by the
// specification) and a base in [0, 1]. A whole exponent, the usual case, is worked by repeated
// squaring in double (at most 7 squarings and 7 products for 128, against a logarithm and an
// exponential of about 150 instructions): its relative error stays below 2^-45, far under the
// float result's 2^-24, and like portable::pow it uses IEEE basic operations only, so it gives
// the same bytes on every machine. On 2.8 million test powers it gives the correctly rounded
// float every time (tests/unit/lighting_equation.cpp). Other exponents go to portable::pow.
inline bool isWholeLightingExponent(float exponent) {
  return exponent >= 0.0f && exponent <= 128.0f &&
         exponent == static_cast<float>(static_cast<int>(exponent));
}
inline float lightingPower(float base, float exponent) {
  if (isWholeLightingExponent(exponent)) {
    double result = 1.0, square = base;
    for (unsigned n = static_cast<unsigned>(exponent); n != 0; n >>= 1) {
      if (n & 1u) result *= square;
      if (n > 1u) square *= square;
    }
    return static_cast<float>(result);
  }
  return portable::pow(base, exponent);
}

// spot_i from PV . s_d: (PV . s_d)^s inside the cone, 0 outside.
inline float spotFactor(float cosine, float cosCutoff, float exponent) {
  if (cosine < cosCutoff) return 0.0f;
  return lightingPower(cosine > 0.0f ? cosine : 0.0f, exponent);
}

// f_i (n . h_i)^s_rm for n . VP_i > 0, with the unit half vector h_i.
inline float specularFactor(float nDotH, float shininess) {
  return lightingPower(nDotH > 0.0f ? nDotH : 0.0f, shininess);
}

// One colour channel of light i's terms: scale * (a_cm a_cli + (n . VP_i) d_cm d_cli), added to
// the sum, and scale * f_i (n . h_i)^s_rm s_cm s_cli, added to the specular sum.
struct LightChannelTerms {
  float lit, specular;
};
inline LightChannelTerms lightChannelTerms(float scale, float diffuseFactor, float specularFactor,
                                           float materialAmbient, float materialDiffuse,
                                           float materialSpecular, float lightAmbient,
                                           float lightDiffuse, float lightSpecular) {
  const float ambient = materialAmbient * lightAmbient;
  const float diffuse = diffuseFactor * materialDiffuse * lightDiffuse;
  const float specular = specularFactor * materialSpecular * lightSpecular;
  return {scale * (ambient + diffuse), scale * specular};
}

// Single colour: everything in c_pri. Separate specular: the specular sum is c_sec.
inline void finishChannel(bool separateSpecular, float sum, float specularSum, float& primary,
                          float& secondary) {
  primary = clamp01(separateSpecular ? sum : sum + specularSum);
  secondary = separateSpecular ? clamp01(specularSum) : 0.0f;
}

}  // namespace glass::gl::lighting_math
