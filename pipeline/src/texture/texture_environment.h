// The texture environment: how the filtered texel combines with the incoming fragment colour
// (OpenGL 1.5 specification, section 3.8.13, tables 3.22 and 3.23).
//
// With Cf, Af the fragment colour, Ct, At (or Lt, It) the texel, Cc, Ac the environment colour:
//   base format      REPLACE        MODULATE            DECAL                      BLEND                          ADD
//   ALPHA            Cf, At         Cf, Af At           (Cf, Af)                   Cf, Af At                      Cf, Af At
//   LUMINANCE        Lt, Af         Cf Lt, Af           (Cf, Af)                   Cf(1-Lt)+Cc Lt, Af             Cf+Lt, Af
//   LUMINANCE_ALPHA  Lt, At         Cf Lt, Af At        (Cf, Af)                   Cf(1-Lt)+Cc Lt, Af At          Cf+Lt, Af At
//   INTENSITY        It, It         Cf It, Af It        (Cf, Af)                   Cf(1-It)+Cc It, Af(1-It)+Ac It Cf+It, Af+It
//   RGB              Ct, Af         Cf Ct, Af           Ct, Af                     Cf(1-Ct)+Cc Ct, Af             Cf+Ct, Af
//   RGBA             Ct, At         Cf Ct, Af At        Cf(1-At)+Ct At, Af         Cf(1-Ct)+Cc Ct, Af At          Cf+Ct, Af At
// DECAL is undefined for the first four base formats; glass leaves the fragment unchanged there,
// as Mesa does. ADD results are clamped to [0, 1].
#pragma once

#include <GL/gl.h>

#include "texture/texture_image.h"

namespace glass::gl {

// Combines `texel` (in the layout of texture_image.h) into `color` (the fragment colour, RGBA
// in [0, 1]) in place.
void applyTextureEnvironment(GLenum mode, BaseFormat base, const float texel[4],
                             const float envColor[4], float color[4]);

}  // namespace glass::gl
