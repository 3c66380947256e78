// The lighting equation (spec 2.13.1) against values worked out by hand. Each case says where its
// expected number comes from.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "lighting/lighting_equation.h"
#include "lighting/lighting_math.h"

using glass::gl::evaluateLighting;
using glass::gl::LightingState;
using glass::gl::Material;

namespace {

struct Lit {
  float primary[4];
  float secondary[4];
};

Lit light(const LightingState& state, const float point[3], const float normal[3],
          int face = glass::gl::kFrontMaterial) {
  Lit out{};
  evaluateLighting(state, state.materials[face], point, normal, out.primary, out.secondary);
  return out;
}

void setColor(float c[4], float r, float g, float b, float a) {
  c[0] = r;
  c[1] = g;
  c[2] = b;
  c[3] = a;
}

// A material that reflects only what a test switches on.
Material blackMaterial() {
  Material m;
  setColor(m.ambient, 0, 0, 0, 1);
  setColor(m.diffuse, 0, 0, 0, 1);
  return m;
}

const float kOrigin[3] = {0, 0, 0};
const float kUp[3] = {0, 0, 1};

}  // namespace

TEST_CASE("lighting: defaults give emission plus scene ambient, alpha from the diffuse material") {
  LightingState s;  // LIGHT0 exists but is disabled
  const Lit lit = light(s, kOrigin, kUp);
  // e_cm + a_cm * a_cs = 0 + 0.2 * 0.2
  CHECK(lit.primary[0] == doctest::Approx(0.04f));
  CHECK(lit.primary[1] == doctest::Approx(0.04f));
  CHECK(lit.primary[2] == doctest::Approx(0.04f));
  CHECK(lit.primary[3] == 1.0f);
  CHECK(lit.secondary[0] == 0.0f);
  CHECK(lit.secondary[3] == 0.0f);
}

TEST_CASE("lighting: GL_LIGHT0 defaults, diffuse follows Lambert's cosine") {
  LightingState s;
  s.lights[0].enabled = true;  // white, directional along +z
  // Facing the light: 0.04 + 1 * 0.8 * 1
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(0.84f));
  // Tilted by 60 degrees: n . L = cos 60 = 0.5, so 0.04 + 0.5 * 0.8
  const float tilted[3] = {std::sin(60.0f * 3.14159265f / 180.0f), 0.0f, 0.5f};
  CHECK(light(s, kOrigin, tilted).primary[1] == doctest::Approx(0.44f));
  // Facing away: only the scene ambient is left (light ambient is 0 for LIGHT0).
  const float away[3] = {0, 0, -1};
  CHECK(light(s, kOrigin, away).primary[2] == doctest::Approx(0.04f));
}

TEST_CASE("lighting: the normal is used as given (no normalization inside the equation)") {
  LightingState s;
  s.lights[0].enabled = true;
  const float twice[3] = {0, 0, 2};
  // n . L = 2: 0.04 + 2 * 0.8 = 1.64, clamped to 1
  CHECK(light(s, kOrigin, twice).primary[0] == 1.0f);
  const float half[3] = {0, 0, 0.5f};
  CHECK(light(s, kOrigin, half).primary[0] == doctest::Approx(0.44f));
}

TEST_CASE("lighting: specular term with the infinite viewer's half vector") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].diffuse, 0, 0, 0, 0.5f);
  setColor(s.materials[0].specular, 0.5f, 0.5f, 0.5f, 1);
  s.materials[0].shininess = 4;
  s.lights[0].enabled = true;
  setColor(s.lights[0].position, 1, 0, 1, 0);  // 45 degrees from the normal
  // h = normalize((0.7071, 0, 0.7071) + (0, 0, 1)), n . h = cos 22.5 = 0.9238795
  // 0.9238795^4 = 0.7285534, times 0.5 * 1
  const Lit lit = light(s, kOrigin, kUp);
  CHECK(lit.primary[0] == doctest::Approx(0.3642767f).epsilon(1e-5));
  CHECK(lit.primary[3] == 0.5f);  // the diffuse alpha, not the specular one
}

TEST_CASE("lighting: local viewer moves the half vector") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].specular, 1, 1, 1, 1);
  s.materials[0].shininess = 1;
  s.lights[0].enabled = true;  // directional along +z
  const float point[3] = {3, 0, -4};
  // Infinite viewer: h = (0, 0, 1), n . h = 1
  CHECK(light(s, point, kUp).primary[0] == doctest::Approx(1.0f));
  // Local viewer: VP_e = (-3, 0, 4) / 5, h = normalize(-0.6, 0, 1.8), n . h = 1.8 / sqrt(3.6)
  s.model.localViewer = true;
  CHECK(light(s, point, kUp).primary[0] == doctest::Approx(0.9486833f).epsilon(1e-5));
}

TEST_CASE("lighting: no specular highlight from a light behind the surface (f_i = 0)") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].ambient, 0.2f, 0.2f, 0.2f, 1);
  setColor(s.materials[0].specular, 1, 1, 1, 1);
  s.materials[0].shininess = 0;  // (n . h)^0 would be 1 everywhere without f_i
  setColor(s.model.ambient, 0, 0, 0, 1);
  s.lights[0].enabled = true;
  setColor(s.lights[0].ambient, 0.5f, 0.5f, 0.5f, 1);
  const float away[3] = {0, 0, -1};
  // Only the light's ambient term: 0.2 * 0.5
  CHECK(light(s, kOrigin, away).primary[0] == doctest::Approx(0.1f));
}

TEST_CASE("lighting: positional light with constant, linear and quadratic attenuation") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].diffuse, 1, 1, 1, 1);
  setColor(s.materials[0].ambient, 1, 1, 1, 1);
  setColor(s.model.ambient, 0, 0, 0, 1);
  s.lights[0].enabled = true;
  setColor(s.lights[0].position, 0, 0, 5, 1);
  setColor(s.lights[0].ambient, 0.1f, 0.1f, 0.1f, 1);
  s.lights[0].constantAttenuation = 1;
  s.lights[0].linearAttenuation = 0.5f;
  s.lights[0].quadraticAttenuation = 0.25f;
  // d = 5: att = 1 / (1 + 2.5 + 6.25) = 1 / 9.75, applied to ambient 0.1 plus diffuse 1
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(1.1f / 9.75f));
  // The same light written with w = 2
  setColor(s.lights[0].position, 0, 0, 10, 2);
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(1.1f / 9.75f));
}

TEST_CASE("lighting: directional lights are not attenuated") {
  LightingState s;
  s.lights[0].enabled = true;
  s.lights[0].constantAttenuation = 4;
  s.lights[0].quadraticAttenuation = 9;
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(0.84f));
}

TEST_CASE("lighting: spotlight cone and exponent") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].diffuse, 1, 1, 1, 1);
  setColor(s.model.ambient, 0, 0, 0, 1);
  s.lights[0].enabled = true;
  setColor(s.lights[0].position, 0, 0, 5, 1);
  s.lights[0].spotDirection[2] = -2;  // not unit length: the equation uses its direction only
  s.lights[0].spotCutoff = 30;
  s.lights[0].spotExponent = 2;
  // Point (1, 0, 0): PV . s_d = 5 / sqrt(26), inside the 30 degree cone. spot = 25 / 26 and
  // n . VP = 5 / sqrt(26).
  const float inside[3] = {1, 0, 0};
  CHECK(light(s, inside, kUp).primary[0] ==
        doctest::Approx(25.0f / 26.0f * 5.0f / std::sqrt(26.0f)));
  // Point (4, 0, 0): PV . s_d = 5 / sqrt(41) = 0.78 < cos 30 = 0.866, outside the cone.
  const float outside[3] = {4, 0, 0};
  CHECK(light(s, outside, kUp).primary[0] == 0.0f);
  // Cutoff 180 turns the spotlight off: the full 5 / sqrt(41)
  s.lights[0].spotCutoff = 180;
  CHECK(light(s, outside, kUp).primary[0] == doctest::Approx(5.0f / std::sqrt(41.0f)));
}

TEST_CASE("lighting: the spotlight factor also applies to directional lights, as the spec says") {
  LightingState s;
  s.lights[0].enabled = true;  // shining along -z
  s.lights[0].spotCutoff = 45;
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(0.84f));
  s.lights[0].spotDirection[0] = 1;
  s.lights[0].spotDirection[2] = 0;  // perpendicular to the light's travel: outside the cone
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(0.04f));
}

TEST_CASE("lighting: separate specular colour moves the specular sum to the secondary colour") {
  LightingState s;
  setColor(s.materials[0].specular, 0.25f, 0.5f, 0.75f, 1);
  s.materials[0].shininess = 8;
  s.lights[0].enabled = true;
  s.model.separateSpecular = true;
  const Lit lit = light(s, kOrigin, kUp);  // n . h = 1: specular = s_cm
  CHECK(lit.primary[0] == doctest::Approx(0.84f));
  CHECK(lit.secondary[0] == doctest::Approx(0.25f));
  CHECK(lit.secondary[1] == doctest::Approx(0.5f));
  CHECK(lit.secondary[2] == doctest::Approx(0.75f));
  CHECK(lit.secondary[3] == 0.0f);
  s.model.separateSpecular = false;
  const Lit single = light(s, kOrigin, kUp);
  CHECK(single.primary[0] == doctest::Approx(1.0f));   // 0.84 + 0.25 clamped
  CHECK(single.primary[2] == doctest::Approx(1.0f));
  CHECK(single.secondary[0] == 0.0f);
}

TEST_CASE("lighting: every one of the eight lights adds its term; disabled lights add nothing") {
  LightingState s;
  s.materials[0] = blackMaterial();
  setColor(s.materials[0].ambient, 1, 1, 1, 1);
  setColor(s.model.ambient, 0, 0, 0, 1);
  for (int i = 0; i < glass::gl::kMaxLights; ++i) {
    setColor(s.lights[i].ambient, 0.01f * static_cast<float>(i + 1), 0, 0, 1);
    s.lights[i].enabled = (i % 2) == 1;  // lights 1, 3, 5, 7
  }
  // 0.02 + 0.04 + 0.06 + 0.08
  CHECK(light(s, kOrigin, kUp).primary[0] == doctest::Approx(0.2f));
}

TEST_CASE("lighting: results are clamped to [0, 1], emission included") {
  LightingState s;
  setColor(s.materials[0].emission, 2.0f, -1.0f, 0.5f, 1);
  setColor(s.model.ambient, 0, 0, 0, 1);
  setColor(s.materials[0].diffuse, 0.8f, 0.8f, 0.8f, 1.5f);
  const Lit lit = light(s, kOrigin, kUp);
  CHECK(lit.primary[0] == 1.0f);
  CHECK(lit.primary[1] == 0.0f);
  CHECK(lit.primary[2] == doctest::Approx(0.5f));
  CHECK(lit.primary[3] == 1.0f);
}

TEST_CASE("lighting: the back material is used when the caller asks for the back face") {
  LightingState s;
  setColor(s.materials[glass::gl::kBackMaterial].emission, 0.0f, 0.5f, 0.0f, 1);
  setColor(s.materials[glass::gl::kBackMaterial].diffuse, 0.0f, 0.0f, 0.0f, 0.25f);
  const Lit lit = light(s, kOrigin, kUp, glass::gl::kBackMaterial);
  CHECK(lit.primary[0] == doctest::Approx(0.04f));
  CHECK(lit.primary[1] == doctest::Approx(0.54f));
  CHECK(lit.primary[3] == 0.25f);
}

TEST_CASE("lighting: homogeneous eye positions are divided by w") {
  float point[3];
  const float position[4] = {2, 4, -6, 2};
  glass::gl::eyePointFromHomogeneous(position, point);
  CHECK(point[0] == 1.0f);
  CHECK(point[1] == 2.0f);
  CHECK(point[2] == -3.0f);
}

TEST_CASE("lighting: whole exponents by repeated squaring give the correctly rounded floats") {
  // lightingPower (lighting_math.h) works whole exponents by squaring in double. Every whole
  // exponent the specification allows (0 to 128), on 20,001 bases spread over [0, 1] and the
  // cosines of 2,000 angles near 0 (where highlights are), against the power worked in long double
  // (64-bit significand) rounded to float, and against portable::pow.
  std::vector<float> bases;
  for (int i = 0; i <= 20000; ++i) bases.push_back(static_cast<float>(i) / 20000.0f);
  for (int i = 0; i < 2000; ++i) bases.push_back(static_cast<float>(std::cos(i * 1e-4)));
  long compared = 0, offCorrect = 0, offPortable = 0;
  for (int exponent = 0; exponent <= 128; ++exponent)
    for (const float base : bases) {
      long double exact = 1.0L;
      for (int k = 0; k < exponent; ++k) exact *= base;
      const float got = glass::gl::lighting_math::lightingPower(base, static_cast<float>(exponent));
      ++compared;
      if (got != static_cast<float>(exact)) {
        ++offCorrect;
        if (offCorrect <= 5) MESSAGE(base << "^" << exponent << ": " << got << " against " << static_cast<float>(exact));
      }
      if (got != glass::portable::pow(base, static_cast<float>(exponent))) ++offPortable;
    }
  CHECK(compared == 129L * 22001L);
  CHECK(offCorrect == 0);
  // portable::pow (a logarithm and an exponential) misses one of them: 0.6875^7 = 19487171 /
  // 2^28 lies half way between two floats, and the even one is the correct one.
  CHECK(offPortable == 1);
  // Other exponents are portable::pow's own.
  CHECK(glass::gl::lighting_math::lightingPower(0.5f, 2.5f) == glass::portable::pow(0.5f, 2.5f));
  CHECK(glass::gl::lighting_math::lightingPower(0.0f, 0.0f) == 1.0f);
}
