// Texture lookups: wrap modes, nearest and linear texel selection and mipmap filtering
// (OpenGL 1.5 specification, sections 3.8.7 to 3.8.9). The texel selection follows the
// specification's integer formulation (as restated in later versions): with u = s * width,
//   NEAREST:  i = wrap(floor(u))
//   LINEAR:   i0 = wrap(floor(u - 1/2)), i1 = wrap(floor(u - 1/2) + 1), alpha = frac(u - 1/2)
//             tau = (1 - alpha)(1 - beta) tau_i0j0 + alpha (1 - beta) tau_i1j0
//                 + (1 - alpha) beta tau_i0j1 + alpha beta tau_i1j1
// where wrap() is, for a level of `size` texels,
//   REPEAT           i mod size
//   MIRRORED_REPEAT  (size - 1) - mirror((i mod 2 size) - size), mirror(a) = a >= 0 ? a : -(1 + a)
//   CLAMP_TO_EDGE    clamp(i, 0, size - 1)
//   CLAMP_TO_BORDER  clamp(i, -1, size)
//   CLAMP            s is first clamped to [0, 1]; then clamp(i, 0, size - 1) for NEAREST and
//                    clamp(i, -1, size) for LINEAR
// and a texel outside the image (i = -1 or i = size) is the border colour. A 3D texture does the
// same along r with GL_TEXTURE_WRAP_R (LINEAR: two slices, mixed by frac(r * depth - 1/2)).
#pragma once

#include "texture/texture_lod.h"
#include "texture/texture_object.h"

namespace glass::gl {

// The border colour of a texture as the texels of its base format see it (spec 3.8.4: the
// border colour is converted to the internal format as table 3.15 does for texels), in the
// layout of texture_image.h.
void borderTexel(const TextureObject& texture, float out[4]);

// Looks up a complete texture at (s, t) (already divided by q; t is ignored for a 1D texture)
// with level of detail lambda: magnification (the TEXTURE_MAG_FILTER on the base level) when
// lambda <= c, minification otherwise. Writes the filtered texel (RGBA in [0, 1], in the layout
// of texture_image.h). For a cube map, (s, t) are on face `face` (cube_map.h); a 3D texture
// reads r as well (already divided by q).
void sampleTexture(const TextureObject& texture, float s, float t, float lambda, float out[4],
                   int face = 0, float r = 0.0f);

// The same lookup with the magnification filter, for primitives without derivatives (points
// and lines) and for the base level (spec 3.8.9).
void sampleTextureMagnified(const TextureObject& texture, float s, float t, float out[4],
                            int face = 0, float r = 0.0f);

}  // namespace glass::gl
