// The arithmetic of LINEAR filtering for colour textures, in fixed point: every texel is 8 bits
// per component, every weight 8 bits, and a filtered component is held with 8 more bits of
// fraction (0 .. 255 * 256 = 65280 for 0 .. 1), as llvmpipe and texturing hardware do. The
// specification leaves the precision of the weights to the implementation (OpenGL 1.5, 3.8.8:
// the formulas are given over the reals); glass fixes it here so that the reference sampler
// (texture_sampler.cpp), the prepared 2D sampler (sampler_2d.h) and the row sampler of the
// fragment kernels (row_sampler_2d-inl.h, 16-bit vector lanes) compute the same integers, and
// so the same bytes on every SIMD target.
//
// For a texel coordinate u (s * size) the LINEAR pair starts at floor(u - 1/2) and its weight
// alpha = frac(u - 1/2) is rounded to 8 bits:
//   U = floor(256 (u - 1/2) + 1/2),  i0 = U >> 8,  a = U & 255  (alpha = a / 256)
// Along a row (and along one axis of a 1D texture) two texels mix exactly:
//   h = t0 (256 - a) + t1 a                                        (0 .. 65280)
// and two such values x0, x1 mix by a 16-bit weight w (0 .. 65535) as
//   x0 + floor(x1 w / 65536) - floor(x0 w / 65536)                 (0 .. 65280)
// which is the exact x0 (1 - w / 65536) + x1 w / 65536 within one unit of the last place, each
// product what a 16-bit vector lane's "multiply high" gives. That mix joins the two rows of a 2D
// lookup and the two slices of a 3D one (w = 256 b, b the 8-bit subtexel weight), and the two
// mipmap levels of *_MIPMAP_LINEAR (w = the level weight rounded to 16 bits, at most 65535:
// levels of very different colours show 8 bits' steps).
// A whole texel t is 256 t; unitFromFixed turns a result into [0, 1] with the same bits as
// t / 255 for whole texels.
//
// Depth textures keep float arithmetic (their texels are depths or comparison results, not
// bytes): texture_sampler.cpp.
#pragma once

#include <algorithm>
#include <cstdint>

#include "texture/texel_addressing.h"

namespace glass::gl::texel_filter {

constexpr int kWeightOne = 256;             // a weight of 1, in 8 fraction bits
constexpr int kFixedMax = 255 * kWeightOne;  // a component of 1

// U = floor(256 u' + 1/2) for u' = u - 1/2, the start of the LINEAR pair in 1/256ths of a
// texel (|u'| <= 2^21 as keepInIntRange leaves it, so 256 u' fits an int).
inline int fixedCoordinate(float uMinusHalf) { return floorToInt(uMinusHalf * 256.0f + 0.5f); }
inline int wholeTexel(int fixed) { return fixed >> 8; }  // floor(U / 256)
inline int subtexelWeight(int fixed) { return fixed & 255; }

// A whole texel component (0 .. 255) as a filtered value.
inline int fixedOfTexel(int texel) { return texel * kWeightOne; }

// t0 (256 - a) + t1 a: two texel components (0 .. 255) along a row.
inline int mixTexels(int t0, int t1, int a) { return t0 * (kWeightOne - a) + t1 * a; }

// x0 + floor(x1 w / 65536) - floor(x0 w / 65536): two filtered values (0 .. 65280) mixed by a
// 16-bit weight w (w / 65536 of x1), as a 16-bit lane's "multiply high" gives each product.
inline int mixFixed(int x0, int x1, int w) {
  const auto high = [w](int x) { return static_cast<int>((static_cast<uint32_t>(x) * static_cast<uint32_t>(w)) >> 16); };
  return x0 + high(x1) - high(x0);
}

// A subtexel weight (0 .. 255) as mixFixed's w.
inline int rowWeight(int subtexel) { return subtexel << 8; }

// A mipmap level weight in [0, 1) as mixFixed's w: rounded to 16 bits, at most 65535.
inline int levelWeight(float weight2) { return std::min(static_cast<int>(weight2 * 65536.0f + 0.5f), 65535); }

// A filtered value as a component in [0, 1]: v / 65280 by one multiplication (for v = 256 t
// the same float as t * (1/255)).
inline float unitFromFixed(int v) { return static_cast<float>(v) * (1.0f / 65280.0f); }

}  // namespace glass::gl::texel_filter
