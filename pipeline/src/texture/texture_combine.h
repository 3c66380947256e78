// The GL_COMBINE texture environment (OpenGL 1.3 section 3.8.13, tables 3.24 and 3.25, with the
// GL 1.4 texture crossbar): each of RGB and alpha is computed by a function of up to three
// arguments,
//   REPLACE       Arg0                    MODULATE     Arg0 * Arg1
//   ADD           Arg0 + Arg1             ADD_SIGNED   Arg0 + Arg1 - 0.5
//   INTERPOLATE   Arg0 * Arg2 + Arg1 * (1 - Arg2)
//   SUBTRACT      Arg0 - Arg1
//   DOT3_RGB      4 * ((r0 - .5)(r1 - .5) + (g0 - .5)(g1 - .5) + (b0 - .5)(b1 - .5)) in R, G, B
//   DOT3_RGBA     the same in R, G, B and A (the alpha function is then not used)
// then multiplied by GL_RGB_SCALE (GL_ALPHA_SCALE) and clamped to [0, 1]. Argument n is source n
// (GL_TEXTURE: this unit's texel; GL_TEXTUREi: unit i's texel; GL_CONSTANT: the environment
// colour; GL_PRIMARY_COLOR: the fragment's colour before texturing; GL_PREVIOUS: what the
// previous unit passed on) through operand n (its colour or alpha, or one minus it).
#pragma once

#include "texture/texture_environment.h"

namespace glass::gl {

// The colours a unit's combiner may read.
struct CombineSources {
  const float* texel = nullptr;             // this unit's filtered texel
  const float* const* unitTexels = nullptr; // per unit; null for a unit that is not textured
  const float* primary = nullptr;           // the fragment's colour entering texturing
  const float* previous = nullptr;          // the previous unit's result (primary for unit 0)
};

// color = the combiner's result for environment env.
void applyCombine(const TextureEnvironment& env, const CombineSources& sources, float color[4]);

// Validity of glTexEnv values for GL_COMBINE (false: GL_INVALID_ENUM).
bool isCombineRGBFunction(GLenum function);
bool isCombineAlphaFunction(GLenum function);
bool isCombineSource(GLenum source);
bool isCombineRGBOperand(GLenum operand);
bool isCombineAlphaOperand(GLenum operand);

}  // namespace glass::gl
