// The batched lighting of the vertex fast path (lighting/batched_lighting.cpp) against the
// lighting equation for one point (evaluateLighting), bit for bit, on every SIMD target this
// machine runs: random lights of every kind (directional, positional with attenuation, spotlights
// with whole and fractional exponents), whole and fractional shininess, local and infinite
// viewer, separate specular colour, both faces, with and without colour material.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <bit>
#include <cstdint>

#include "core/simd_dispatch.h"
#include "lcg_random.h"
#include "lighting/batched_lighting.h"
#include "lighting/color_material.h"
#include "lighting/lighting_equation.h"

using glass::gl::kLightingBatch;
using glass::gl::LightingInput;
using glass::gl::LightingState;
using glass::gl::LitColorRows;
using glass::gl::Material;
using glass::gl::SimdTarget;

namespace {

struct Random : LcgRandom {
  float unit() { return static_cast<float>(next() >> 29) / 16777216.0f; }  // [0, 1)
  float between(float low, float high) { return low + (high - low) * unit(); }
  bool coin() { return (next() & 1u) != 0; }
};

// An exponent in [0, 128]: half of them whole (the squaring path), some at the ends.
float someExponent(Random& random) {
  switch (random.next() % 6) {
    case 0: return 0.0f;
    case 1: return 128.0f;
    case 2:
    case 3: return static_cast<float>(random.next() % 129);
    default: return random.between(0.0f, 128.0f);
  }
}

void randomColor(Random& random, float c[4]) {
  for (int i = 0; i < 4; ++i) c[i] = random.between(0.0f, 1.0f);
}

LightingState randomState(Random& random) {
  LightingState state;
  state.enabled = true;
  for (auto& material : state.materials) {
    randomColor(random, material.ambient);
    randomColor(random, material.diffuse);
    randomColor(random, material.specular);
    randomColor(random, material.emission);
    material.shininess = someExponent(random);
  }
  randomColor(random, state.model.ambient);
  state.model.localViewer = random.coin();
  state.model.twoSide = random.coin();
  state.model.separateSpecular = random.coin();
  const int lights = 1 + static_cast<int>(random.next() % 3);
  for (int l = 0; l < lights; ++l) {
    auto& light = state.lights[random.next() % glass::gl::kMaxLights];
    light.enabled = true;
    randomColor(random, light.ambient);
    randomColor(random, light.diffuse);
    randomColor(random, light.specular);
    for (int c = 0; c < 3; ++c) light.position[c] = random.between(-4.0f, 4.0f);
    light.position[3] = random.coin() ? 0.0f : random.between(0.5f, 2.0f);
    if (random.coin()) {
      light.constantAttenuation = random.between(0.5f, 2.0f);
      light.linearAttenuation = random.between(0.0f, 1.0f);
      light.quadraticAttenuation = random.between(0.0f, 0.5f);
    }
    if (random.next() % 3 != 0) {
      for (int c = 0; c < 3; ++c) light.spotDirection[c] = random.between(-1.0f, 1.0f);
      light.spotCutoff = random.coin() ? 90.0f : random.between(5.0f, 85.0f);
      light.spotExponent = someExponent(random);
    }
  }
  const GLenum modes[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
  const GLenum faces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
  state.colorMaterial.enabled = random.coin();
  state.colorMaterial.mode = modes[random.next() % 5];
  state.colorMaterial.face = faces[random.next() % 3];
  return state;
}

// Vertices round the lights and the eye; normals of every length, a few zero.
void randomVertices(Random& random, LightingInput& in, float (*colors)[kLightingBatch]) {
  in.count = 1 + static_cast<int>(random.next() % kLightingBatch);
  for (int i = 0; i < in.count; ++i) {
    for (int c = 0; c < 3; ++c) in.point[c][i] = random.between(-3.0f, 3.0f);
    in.point[2][i] -= 5.0f;
    const bool zero = random.next() % 16 == 0;
    for (int c = 0; c < 3; ++c) in.normal[c][i] = zero ? 0.0f : random.between(-1.5f, 1.5f);
    for (int c = 0; c < 4; ++c) colors[c][i] = random.between(0.0f, 1.0f);
  }
}

// What evaluateLighting gives vertex i of `in` for `face`, its material as the batch builds it.
void expectedColors(const LightingState& state, int face, bool reverseNormal,
                    const LightingInput& in, int i, float primary[4], float secondary[4]) {
  Material material = state.materials[face];
  if (in.color != nullptr) {
    float* parameters[4] = {material.ambient, material.diffuse, material.specular, material.emission};
    const GLenum names[4] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
    for (int p = 0; p < 4; ++p)
      if (glass::gl::tracksCurrentColor(state.colorMaterial, face, names[p]))
        for (int c = 0; c < 4; ++c) parameters[p][c] = in.color[c][i];
  }
  const float point[3] = {in.point[0][i], in.point[1][i], in.point[2][i]};
  float normal[3] = {in.normal[0][i], in.normal[1][i], in.normal[2][i]};
  if (reverseNormal)
    for (float& n : normal) n = -n;
  glass::gl::evaluateLighting(state, material, point, normal, primary, secondary);
}

bool sameBits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

}  // namespace

TEST_CASE("lighting_batch_matches_equation: batched vertices get evaluateLighting's bits on every SIMD target") {
  long compared = 0, mismatches = 0;
  int targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::gl::simdTargetRuns(target)) continue;
    ++targets;
    Random random{{20261205u}};
    for (int round = 0; round < 1500; ++round) {
      const LightingState state = randomState(random);
      LightingInput in;
      float colors[4][kLightingBatch];
      randomVertices(random, in, colors);
      in.color = state.colorMaterial.enabled ? colors : nullptr;
      for (int face = 0; face < 2; ++face) {
        const bool reverseNormal = face == glass::gl::kBackMaterial;
        LitColorRows out;
        glass::gl::lightBatchWith(target, state, face, reverseNormal, in, out);
        for (int i = 0; i < in.count; ++i) {
          float primary[4], secondary[4];
          expectedColors(state, face, reverseNormal, in, i, primary, secondary);
          for (int c = 0; c < 4; ++c) {
            compared += 2;
            if ((!sameBits(primary[c], out.primary[c][i]) ||
                 !sameBits(secondary[c], out.secondary[c][i])) &&
                ++mismatches <= 10)
              MESSAGE("target ", t, " round ", round, " face ", face, " vertex ", i, " channel ", c,
                      ": ", primary[c], "/", secondary[c], " vs ", out.primary[c][i], "/",
                      out.secondary[c][i]);
          }
        }
      }
    }
  }
  CHECK(targets >= 1);
  CHECK(compared > 1000000);
  CHECK(mismatches == 0);
}
