// GL_GENERATE_MIPMAP (OpenGL 1.5 specification, section 3.8.8, "Automatic Mipmap Generation"):
// when the base level of a texture with GENERATE_MIPMAP set changes, levels base + 1 .. q are
// derived from it. The specification leaves the filter open and suggests a 2 x 2 box; glass
// uses a box filter over the exact footprint of each derived texel: for even sizes that is the
// average of 2 x 2 texels (rounded to nearest, halves up, as GLU's box filter rounds); for odd
// sizes each derived texel averages the 2 or 3 texels it covers, weighted by the share it covers.
#pragma once

#include "texture/texture_image.h"
#include "texture/texture_object.h"

namespace glass::gl {

// One derived image: `source` reduced to max(1, w / 2) x max(1, h / 2) (x max(1, d / 2) for a 3D
// image) by the box filter above.
// The result has the internal format, base format and border of `source`.
TextureImage reduceImageByBoxFilter(const TextureImage& source);

// Replaces levels base + 1 .. q of `texture` (of its cube map face `face`) with images derived
// from the base level (q = min(p, TEXTURE_MAX_LEVEL) as in section 3.8.10), then updates its
// completeness.
void generateMipmaps(TextureObject& texture, int face = 0);

}  // namespace glass::gl
