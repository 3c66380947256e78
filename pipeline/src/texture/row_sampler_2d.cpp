// sampleTextureRowWith (texture/row_sampler_2d.h): texture/row_sampler_2d-inl.h compiled once per
// SIMD target, as the fragment kernels compile it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "texture/row_sampler_2d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "texture/row_sampler_2d-inl.h"
#include "texture/row_sampler_2d.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {

void SampleTextureRow(const Sampler2D& sampler, const float* s, const float* t,
                      const Sampler2D::LevelChoice* quadChoice, unsigned mask,
                      float texel[4][kSampledRowPixels]) {
  static_assert(row_sampler::kRowPixels == kSampledRowPixels);
  row_sampler::sampleRow(sampler, s, t, quadChoice, mask, texel);
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(SampleTextureRow))> kSampleTextureRow =
    GLASS_SIMD_FUNCTIONS(SampleTextureRow);

void sampleTextureRowWith(SimdTarget target, const Sampler2D& sampler, const float* s, const float* t,
                          const Sampler2D::LevelChoice* quadChoice, unsigned mask,
                          float texel[4][kSampledRowPixels]) {
  kSampleTextureRow[static_cast<int>(target)](sampler, s, t, quadChoice, mask, texel);
}

}  // namespace glass::gl
#endif  // HWY_ONCE
