// levelsOfDetailWith (texture/level_of_detail.h): texture/level_of_detail-inl.h compiled once per
// SIMD target, as the fragment kernels compile it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "texture/level_of_detail.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "texture/level_of_detail-inl.h"
#include "texture/level_of_detail.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {

void LevelsOfDetail(const double* rhoSquared, float minLod, float maxLod, float bias, float* lambda) {
  static_assert(level_of_detail::kQuads == kLevelOfDetailQuads);
  level_of_detail::levelsOfDetail(rhoSquared, minLod, maxLod, bias, lambda);
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(LevelsOfDetail))> kLevelsOfDetail =
    GLASS_SIMD_FUNCTIONS(LevelsOfDetail);

void levelsOfDetailWith(SimdTarget target, const double* rhoSquared, float minLod, float maxLod, float bias,
                        float* lambda) {
  kLevelsOfDetail[static_cast<int>(target)](rhoSquared, minLod, maxLod, bias, lambda);
}

}  // namespace glass::gl
#endif  // HWY_ONCE
