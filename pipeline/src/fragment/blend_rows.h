// blend() (blending.h) on the eight pixels of a block row at once, for the block kernels
// (block_kernels.h): every pixel's bytes as blend() gives them, for every equation, factor and
// blend colour. Compiled for every SIMD target (glass/raster/simd_target.h), a pixel per lane,
// each lane doing blend()'s integer arithmetic exactly (blend_rows.cpp), so every target gives its
// bytes; the unit test blend_rows compares them pixel by pixel.
#pragma once

#include <cstdint>

#include "fragment/blending.h"
#include "glass/raster/simd_target.h"

namespace glass::gl {

inline constexpr int kBlendRowPixels = 8;

// result[i] = blend(settings, source[i], destination[i]) for the kBlendRowPixels RGBA8 pixels,
// each held as 4 bytes in the colour buffer's order.
using BlendRow = void (*)(const BlendSettings& settings, const uint32_t source[kBlendRowPixels],
                          const uint32_t destination[kBlendRowPixels], uint32_t result[kBlendRowPixels]);

// The row for the settings, chosen once per draw: for the common settings (kCommonBlends) a copy
// compiled with their equation and factors, for the others one that reads them; the copy of
// the SIMD target the kernels run with.
BlendRow blendRowFor(const BlendSettings& settings);
// The same compiled for `target` (tests; the target must run here).
BlendRow blendRowFor(raster::SimdTarget target, const BlendSettings& settings);

}  // namespace glass::gl
