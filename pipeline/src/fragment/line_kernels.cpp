// The kernels of line_kernels.h: one template, specialised by the key.
//
// Equality with the reference path (FragmentProcessor::processFragments), value by value, for the
// states a kernel is chosen for:
//   colour    the reference path's colour is the fragment's varyings 0-3, untouched by the
//             stages that are off, converted by floatToColorByte and stored as one word
//             (packColorBytes). Every fragment of a run has the same varyings, so the kernel
//             converts them once per run into the same word, the batch's runs four at a time
//             (packColorColumns: the same conversion on the lanes of vectors).
//   depth     the reference path's own function, testStencilAndDepth (without a stencil
//             buffer), on each fragment in the same order, so a fragment that lands on a pixel an
//             earlier fragment of the batch wrote is tested against that write, as there.
// No floating point beyond that conversion, whose lanes are the scalar operations, and nothing
// compiled per SIMD target, so the bytes are the same on every target.
#include "fragment/line_kernels.h"

#include <cstring>

#include "fragment/color_conversion.h"

namespace glass::gl {
namespace {

template <bool depthTest, bool writeColor>
void shadeLineRuns(raster::Framebuffer& framebuffer, const StencilDepthSettings& tests,
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
    packColorColumns(components, batch.count, words);
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

LineKernel lineKernelFor(const LineKernelKey& key) {
  if (key.depthTest) return key.writeColor ? shadeLineRuns<true, true> : shadeLineRuns<true, false>;
  return key.writeColor ? shadeLineRuns<false, true> : shadeLineRuns<false, false>;
}

}  // namespace glass::gl
