// The kernels of line_kernels.h: one template, specialised by the key, compiled once for each
// SIMD target (hwy/foreach_target.h re-includes this file per target); lineKernelFor takes the
// copy of the chosen target (glass/raster/simd_target.h), as blockKernelFor does.
//
// Equality with the reference path (FragmentProcessor::processFragments), value by value, for the
// states a kernel is chosen for:
//   colour    the reference path's colour is the fragment's varyings 0-3, untouched by the
//             stages that are off, converted by floatToColorByte and stored as one word
//             (packColorBytes). Every fragment of a run has the same varyings, so the kernel
//             converts them once per run into the same word, the batch's runs a vector at a time
//             (PackColorColumns, with color_packing-inl.h's lanes: the scalar operations),
//             ORed with alpha 255 without alpha bitplanes as the reference path's store is.
//   depth     the reference path's own function, testStencilAndDepth (without a stencil
//             buffer), on each fragment in the same order, so a fragment that lands on a pixel an
//             earlier fragment of the batch wrote is tested against that write, as there.
// No floating point beyond that conversion, one IEEE operation per lane, so the bytes are the
// same on every target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fragment/line_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstring>

#include "core/simd_dispatch.h"
#include "fragment/color_packing-inl.h"
#include "fragment/line_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

void PackColorColumns(const float* const component[4], int count, uint32_t* words) {
  const hn::CappedTag<float, 16> f;
  const int lanes = static_cast<int>(hn::Lanes(f));
  int i = 0;
  for (; i + lanes <= count; i += lanes)
    color_packing::packColorVector(f, component[0] + i, component[1] + i, component[2] + i, component[3] + i,
                                   words + i);
  if (i == count) return;
  // The last colours, fewer than a vector, from a copy padded with zeros.
  const int rest = count - i;
  alignas(64) float padded[4][16] = {};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < rest; ++k) padded[c][k] = component[c][i + k];
  alignas(64) uint32_t restWords[16];
  color_packing::packColorVector(f, padded[0], padded[1], padded[2], padded[3], restWords);
  for (int k = 0; k < rest; ++k) words[i + k] = restWords[k];
}

namespace {

template <bool depthTest, bool writeColor>
void shadeLineRuns(raster::Framebuffer& framebuffer, const StencilDepthSettings& tests, uint32_t storedAlpha,
                   const raster::LineRunBatch& batch) {
  uint8_t* const colors = framebuffer.colorAt(0, 0);
  uint32_t* const depths = framebuffer.depthAt(0, 0);
  const size_t width = static_cast<size_t>(framebuffer.width());
  // From one fragment of a run to the next: one pixel to the right, or one row up.
  const size_t step = batch.alongX ? 1 : width;
  uint32_t words[raster::LineRunBatch::kMaxRuns];
  if constexpr (writeColor) {
    const float* const components[4] = {batch.varyings[0], batch.varyings[1], batch.varyings[2],
                                        batch.varyings[3]};
    PackColorColumns(components, batch.count, words);
    if (storedAlpha != 0) {
      for (int r = 0; r < batch.count; ++r) words[r] |= storedAlpha;
    }
  }
  for (int r = 0; r < batch.count; ++r) {
    size_t index = static_cast<size_t>(batch.y[r]) * width + static_cast<size_t>(batch.x[r]);
    for (int i = 0; i < batch.length[r]; ++i, index += step) {
      if constexpr (depthTest) {
        if (testStencilAndDepth(tests, nullptr, depths + index, batch.depth[r]) !=
            StencilDepthOutcome::Passed)
          continue;
      }
      if constexpr (writeColor) std::memcpy(colors + 4 * index, &words[r], 4);
    }
  }
}

}  // namespace

// The kernel for (depthTest, writeColor), indexed as kernelIndex below.
LineKernel LineKernelAt(int index) {
  static constexpr LineKernel kKernels[4] = {shadeLineRuns<false, false>, shadeLineRuns<true, false>,
                                             shadeLineRuns<false, true>, shadeLineRuns<true, true>};
  return kKernels[index];
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {

constexpr SimdFunctions<LineKernel (*)(int)> kLineKernelAt = GLASS_SIMD_FUNCTIONS(LineKernelAt);
constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(PackColorColumns))> kPackColorColumns =
    GLASS_SIMD_FUNCTIONS(PackColorColumns);

LineKernel lineKernelFor(const LineKernelKey& key) {
  return chosenSimdFunction(kLineKernelAt)((key.depthTest ? 1 : 0) | (key.writeColor ? 2 : 0));
}

void packColorColumnsWith(SimdTarget target, const float* const component[4], int count, uint32_t* words) {
  kPackColorColumns[static_cast<int>(target)](component, count, words);
}

}  // namespace glass::gl
#endif  // HWY_ONCE
