// Small pieces shared by the quadric generators. GLU computes angles in double, stores them and
// their sines and cosines in float, and mixes float and double in its arithmetic; the helpers
// here round at the same places, so glass emits bit for bit the vertices GLU emits.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glu/quadric_emitter.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::glu {

inline constexpr double kPi = std::numbers::pi;

// One table entry per slice or stack, plus the wrap-around entry.
inline constexpr int kQuadricTableSize = kMaxQuadricDivisions + 2;

// An angle rounded to float, then its sine and cosine (evaluated in double) rounded to float.
struct SineCosine {
  float sine, cosine;
};
inline SineCosine sineCosineOf(double angle) {
  const double a = static_cast<float>(angle);
  return {static_cast<float>(portable::sin(a)), static_cast<float>(portable::cos(a))};
}

// The fraction k / n rounded to float, as GLU's (float) k / n.
inline float fraction(int k, int n) { return static_cast<float>(k) / static_cast<float>(n); }

// The texture coordinate 1 - k / n, in float.
inline float oneMinusFraction(int k, int n) { return 1.0f - fraction(k, n); }

inline int clampDivisions(int n) { return std::min(n, kMaxQuadricDivisions); }

}  // namespace glass::gl::glu
