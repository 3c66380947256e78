// Bump mapping (the GL_GLASS_bump_map extension; Blinn 1978, as in Buss, "3-D Computer Graphics",
// chapter V.2): a height function d(s, t), read from a height-map texture, displaces the surface
// along its normal, p*(s, t) = p(s, t) + d(s, t) N. Only the normal of the displaced surface is
// used, so the geometry stays flat while the lighting sees the bumps.
//
// With P_s = dp/ds and P_t = dp/dt (the surface's tangents along the texture axes) and N the unit
// normal, and d small enough that the derivatives of N can be dropped:
//   dp*/ds = P_s + d_s N,   dp*/dt = P_t + d_t N
//   n* = dp*/ds x dp*/dt = P_s x P_t + d_s (N x P_t) - d_t (N x P_s)
// Dividing by |P_s x P_t| (and orienting P_s x P_t along N):
//   n* ~ N + (d_s (N x P_t) - d_t (N x P_s)) / |P_s x P_t|.
//
// glass needs no tangent attributes for this: per fragment, the screen-space derivatives of the
// eye position and of (s, t), both exact (the rasterizer's attribute planes), give P_s and P_t by
// the chain rule,
//   dP/dx = P_s ds/dx + P_t dt/dx,   dP/dy = P_s ds/dy + P_t dt/dy,
// a 2 x 2 linear system. d_s and d_t are central differences of the height map one texel apart.
#pragma once

#include "texture/texture_lod.h"
#include "texture/texture_object.h"

namespace glass::gl {

// Perturbs `normal` (eye space; its length is kept) at a fragment with texture coordinates
// (s, t) and derivatives `st`, eye-position derivatives dPdx/dPdy, using the red channel (or
// luminance) of the complete 2D texture `heightMap` times `scale` as the height d. Leaves the
// normal unchanged where the texture coordinates do not vary across the surface (no P_s, P_t).
void perturbNormalByHeightMap(const TextureObject& heightMap, float scale, float s, float t,
                              const TexCoordDerivatives& st, const double dPdx[3],
                              const double dPdy[3], float normal[3]);

}  // namespace glass::gl
