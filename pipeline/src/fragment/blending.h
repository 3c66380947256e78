// Blending (spec 4.1.7, GL 1.4 tables 4.1 and 4.2): source and destination factors, the blend
// colour, and the blend equations ADD, SUBTRACT, REVERSE_SUBTRACT, MIN and MAX.
//
// The colour buffer holds 8-bit components, and blending works in that fixed point, as the spec
// permits and Mesa's drivers do: colours and factors are 8-bit values v standing for v / 255,
// each product s * f is rounded to the nearest 8-bit value (s * f / 255, never a tie), and the
// sum or difference saturates to [0, 255].
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glass::gl {

struct BlendSettings {
  GLenum srcRGB = GL_ONE, dstRGB = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;
  GLenum equation = GL_FUNC_ADD;
  uint8_t constant[4] = {0, 0, 0, 0};  // glBlendColor, converted to 8 bits

  bool operator==(const BlendSettings&) const = default;
};

bool isBlendFactor(GLenum factor, bool source);
bool isBlendEquation(GLenum equation);

// source: the fragment's colour; destination: the colour buffer's. Writes the blended colour.
void blend(const BlendSettings& settings, const uint8_t source[4], const uint8_t destination[4],
           uint8_t result[4]);

// The settings programs use most, each with GL_FUNC_ADD and the same factors for colour and
// alpha, for which blendFunctionFor and the blend rows (blend_rows.h) have copies compiled with
// the equation and factors as constants.
struct CommonBlend {
  GLenum source, destination;
};
inline constexpr CommonBlend kCommonBlends[] = {
    {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},  // transparency, antialiased lines and points
    {GL_ONE, GL_ONE_MINUS_SRC_ALPHA},        // premultiplied alpha
    {GL_SRC_ALPHA, GL_ONE},                  // additive glow, particles
    {GL_ONE, GL_ONE},                        // additive
    {GL_DST_COLOR, GL_ZERO},                 // modulation (light maps, multipass)
    {GL_ZERO, GL_SRC_COLOR},
};
inline constexpr int kCommonBlendCount = static_cast<int>(sizeof kCommonBlends / sizeof kCommonBlends[0]);

// The index in kCommonBlends of the settings' equation and factors, or -1.
int commonBlendIndex(const BlendSettings& settings);

// A function that blends one pixel as blend() does, chosen once per draw by blendFunctionFor:
// for the settings programs use most (transparency and antialiasing with GL_SRC_ALPHA,
// GL_ONE_MINUS_SRC_ALPHA, additive and premultiplied blending, modulation) a copy of blend()
// compiled with the equation and the four factors as constants, so that its switches fold
// away; blend() itself for every other setting. The same bytes either way (the unit test "the
// blend function chosen for a setting gives blend()'s bytes").
using BlendFunction = void (*)(const BlendSettings& settings, const uint8_t source[4],
                               const uint8_t destination[4], uint8_t result[4]);
BlendFunction blendFunctionFor(const BlendSettings& settings);

}  // namespace glass::gl
