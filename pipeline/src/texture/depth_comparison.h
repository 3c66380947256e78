// Sampling a depth texture (OpenGL 1.4 specification, sections 3.8.13 and 3.8.14;
// GL_ARB_depth_texture, GL_ARB_shadow, and the eight functions of GL_EXT_shadow_funcs).
//
// Each texel the filter reads is first turned into a value: with GL_TEXTURE_COMPARE_MODE
// GL_COMPARE_R_TO_TEXTURE, the comparison of the fragment's r (clamped to [0, 1]) with the
// texel's depth D_t (1 when `r func D_t` holds, else 0; LEQUAL: r <= D_t); with GL_NONE, D_t
// itself. Texels outside the image take the border colour's red as D_t. Then the filter mixes
// these values as it mixes colour texels, so a LINEAR filter gives the fraction of the four
// texels the comparison passes (percentage-closer filtering: the specification allows any
// weighting close to it, and this is how Mesa's llvmpipe weighs them). The value becomes a
// luminance, intensity or alpha texel by GL_DEPTH_TEXTURE_MODE (3.8.13), which is also the base
// format the texture environment sees.
#pragma once

#include "texture/texture_object.h"

namespace glass::gl {

struct DepthLookup {
  bool compare = false;
  GLenum func = GL_LEQUAL;
  float reference = 0.0f;  // r clamped to [0, 1]
  float borderDepth = 0.0f;
  BaseFormat base = BaseFormat::Luminance;
};

// Whether `texture` is a depth texture; if so, fills `lookup` for a fragment with coordinate r
// (already divided by q).
bool depthLookupOf(const TextureObject& texture, float r, DepthLookup* lookup);

// Texel (i, j) of depth image `image` (outside it: the border depth) as the filter reads it:
// components in [0, 255] in the layout of texture_image.h for the lookup's base format.
const float* depthTexel(const DepthLookup& lookup, const TextureImage& image, int i, int j,
                        float scratch[4]);

// The base format the texture environment sees (tables 3.22 and 3.23): the image's, or for a
// depth texture the one GL_DEPTH_TEXTURE_MODE names.
BaseFormat environmentBaseFormat(const TextureObject& texture);

}  // namespace glass::gl
