// Blending (spec 4.1.7, GL 1.4 tables 4.1 and 4.2): source and destination factors, the blend
// colour, and the blend equations ADD, SUBTRACT, REVERSE_SUBTRACT, MIN and MAX. Computed in float
// on colours in [0, 1]; the result is clamped to [0, 1].
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct BlendSettings {
  GLenum srcRGB = GL_ONE, dstRGB = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;
  GLenum equation = GL_FUNC_ADD;
  float constant[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};

bool isBlendFactor(GLenum factor, bool source);
bool isBlendEquation(GLenum equation);

// source: the fragment's colour; destination: the colour buffer's. Writes the blended colour.
void blend(const BlendSettings& settings, const float source[4], const float destination[4],
           float result[4]);

}  // namespace glass::gl
