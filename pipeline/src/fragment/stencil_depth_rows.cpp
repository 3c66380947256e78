// testStencilAndDepthRowWith (fragment/stencil_depth_rows.h): fragment/stencil_depth_rows-inl.h
// compiled once per SIMD target, as the block kernels compile it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fragment/stencil_depth_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "core/simd_dispatch.h"
#include "fragment/stencil_depth_rows-inl.h"
#include "fragment/stencil_depth_rows.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {

unsigned TestStencilAndDepthRow(const StencilDepthSettings& settings, uint8_t* stencil, uint32_t* depth,
                                const uint32_t* fragmentDepth, unsigned mask) {
  static_assert(stencil_depth_rows::kRowPixels == kStencilDepthRowPixels);
  return stencil_depth_rows::testStencilAndDepthRow(settings, stencil, depth, fragmentDepth, mask);
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(TestStencilAndDepthRow))> kTestStencilAndDepthRow =
    GLASS_SIMD_FUNCTIONS(TestStencilAndDepthRow);

unsigned testStencilAndDepthRowWith(raster::SimdTarget target, const StencilDepthSettings& settings,
                                    uint8_t* stencil, uint32_t* depth, const uint32_t* fragmentDepth,
                                    unsigned mask) {
  return kTestStencilAndDepthRow[static_cast<int>(target)](settings, stencil, depth, fragmentDepth, mask);
}

}  // namespace glass::gl
#endif  // HWY_ONCE
