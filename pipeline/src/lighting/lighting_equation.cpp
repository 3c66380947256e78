// The OpenGL 1.x lighting equation (OpenGL 1.5 specification, section 2.13.1):
//
//   c_pri = e_cm                                           emission
//         + a_cm * a_cs                                    scene ambient
//         + sum over enabled lights i of
//             att_i * spot_i * ( a_cm * a_cli              ambient
//                              + (n . VP_i) d_cm * d_cli   diffuse (Lambert)
//                              + f_i (n . h_i)^s_rm s_cm * s_cli )   specular (Blinn-Phong)
//
// where "." is the dot product clamped at 0, VP_i the unit vector from the point to the light,
// h_i the unit half vector and f_i = 1 when n . VP_i > 0, else 0. With
// GL_SEPARATE_SPECULAR_COLOR the specular sum goes to the secondary colour c_sec instead.
// docs/lighting.md explains each term and points back here.
#include "lighting/lighting_equation.h"

#include <cmath>

#include "lighting/lighting_math.h"

namespace glass::gl {
namespace {

using lighting_math::clamp01;
using lighting_math::dot3;
using lighting_math::normalize3;

// The geometry of one light seen from the point V: the unit vector VP to the light, its
// attenuation att and spotlight factor spot.
struct LightGeometry {
  float toLight[3];    // VP_i, unit length
  float attenuation;   // att_i
  float spot;          // spot_i
};

LightGeometry lightGeometry(const LightSource& light, const float eyePoint[3]) {
  LightGeometry g;
  const float* p = light.position;
  if (p[3] == 0.0f) {
    // Directional light: the position is a direction towards the light, the same at every point,
    // and att_i = 1.
    lighting_math::directionalToLight(light, g.toLight);
    g.attenuation = 1.0f;
  } else {
    // Positional light at P / w: VP = P - V, and
    //   att_i = 1 / (k0 + k1 * |VP| + k2 * |VP|^2).
    const float inverseW = 1.0f / p[3];
    g.toLight[0] = p[0] * inverseW - eyePoint[0];
    g.toLight[1] = p[1] * inverseW - eyePoint[1];
    g.toLight[2] = p[2] * inverseW - eyePoint[2];
    const float distanceSquared = dot3(g.toLight, g.toLight);
    const float distance = std::sqrt(distanceSquared);
    g.attenuation = 1.0f / (light.constantAttenuation + light.linearAttenuation * distance +
                            light.quadraticAttenuation * distanceSquared);
    normalize3(g.toLight);
  }

  // Spotlight: with cutoff c and exponent s, and PV the unit vector from the light to the point,
  //   spot_i = (PV . s_d)^s  when PV . s_d >= cos(c),   0 when outside the cone,   1 when c = 180.
  // The specification applies it to directional lights too (PV = -VP), and so does Mesa; the
  // direction s_d is used as a unit vector.
  g.spot = 1.0f;
  if (light.spotCutoff != 180.0f) {
    float direction[3];
    lighting_math::unitSpotDirection(light, direction);
    const float cosine = -dot3(g.toLight, direction);
    g.spot = lighting_math::spotFactor(cosine, lighting_math::spotCosCutoff(light),
                                       light.spotExponent);
  }
  return g;
}

}  // namespace

void eyePointFromHomogeneous(const float eyePosition[4], float point[3]) {
  for (int c = 0; c < 3; ++c) point[c] = eyeCoordinateFromHomogeneous(eyePosition[c], eyePosition[3]);
}

void evaluateLighting(const LightingState& state, const Material& material,
                      const float eyePoint[3], const float normal[3], float primary[4],
                      float secondary[4], LightingTerms* trace) {
  // Emission plus the scene's ambient light: e_cm + a_cm * a_cs.
  float sum[3], specularSum[3] = {0.0f, 0.0f, 0.0f};
  for (int c = 0; c < 3; ++c) {
    sum[c] = material.emission[c] + material.ambient[c] * state.model.ambient[c];
    if (trace) trace->base[c] = sum[c];
  }
  if (trace) trace->lightCount = 0;

  // The unit vector from the point to the eye, VP_e: the eye sits at the origin of eye space
  // (local viewer), or infinitely far along +z (the default, cheaper and the same everywhere).
  float toEye[3] = {0.0f, 0.0f, 1.0f};
  if (state.model.localViewer) {
    toEye[0] = -eyePoint[0];
    toEye[1] = -eyePoint[1];
    toEye[2] = -eyePoint[2];
    normalize3(toEye);
  }

  for (const LightSource& light : state.lights) {
    if (!light.enabled) continue;
    const LightGeometry g = lightGeometry(light, eyePoint);
    const float scale = g.attenuation * g.spot;
    LightingTerms::Light* traced = nullptr;
    if (trace) {
      traced = &trace->lights[trace->lightCount++];
      *traced = LightingTerms::Light{};
      traced->index = static_cast<int>(&light - state.lights);
      traced->attenuation = g.attenuation;
      traced->spot = g.spot;
      traced->nDotL = dot3(normal, g.toLight);
    }
    if (scale == 0.0f) continue;

    // Lambert's cosine n . VP_i, clamped at 0: light from behind the surface does not reach it.
    const float nDotL = dot3(normal, g.toLight);
    const float diffuseFactor = nDotL > 0.0f ? nDotL : 0.0f;

    // Blinn's half vector h_i = VP_i + VP_e (normalized) and the specular factor
    // f_i * (n . h_i)^s_rm, with f_i = 0 when the light is behind the surface.
    float specularFactor = 0.0f;
    if (nDotL > 0.0f) {
      float half[3] = {g.toLight[0] + toEye[0], g.toLight[1] + toEye[1], g.toLight[2] + toEye[2]};
      normalize3(half);
      specularFactor = lighting_math::specularFactor(dot3(normal, half), material.shininess);
    }

    for (int c = 0; c < 3; ++c) {
      const lighting_math::LightChannelTerms terms = lighting_math::lightChannelTerms(
          scale, diffuseFactor, specularFactor, material.ambient[c], material.diffuse[c],
          material.specular[c], light.ambient[c], light.diffuse[c], light.specular[c]);
      sum[c] += terms.lit;
      specularSum[c] += terms.specular;
      if (traced) {
        traced->ambient[c] = scale * material.ambient[c] * light.ambient[c];
        traced->diffuse[c] = scale * diffuseFactor * material.diffuse[c] * light.diffuse[c];
        traced->specular[c] = terms.specular;
      }
    }
    if (traced) traced->specularFactor = specularFactor;
  }

  // Single colour: everything in c_pri. Separate specular: the specular sum is c_sec (alpha 0).
  const bool separate = state.model.separateSpecular;
  for (int c = 0; c < 3; ++c) {
    lighting_math::finishChannel(separate, sum[c], specularSum[c], primary[c], secondary[c]);
  }
  // The alpha of a lit colour is the alpha of the material's diffuse reflectance.
  primary[3] = clamp01(material.diffuse[3]);
  secondary[3] = 0.0f;
}

}  // namespace glass::gl
