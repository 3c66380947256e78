// The kernels of block_kernels.h: one template, specialised by the key.
//
// Equality with the reference path, value by value:
//   depth     the triangle walk computed it; the reference path's depth test after the early
//             test passes for the same fragments (the stored value has not changed in between:
//             a block holds each pixel once), so the kernel only stores it.
//   varyings  the reference path (emitBlockFragments, rasterizer/src/triangle_rasterize.cpp)
//             computes float((p_column + p_row) / (q_column + q_row)) with p_column = a0 + dx x,
//             p_row = dy y, q_column = invW0 + invWdx x, q_row = invWdy y at the pixel centre;
//             BlockVaryings does exactly that, for the slots the key needs only. When the 1/w
//             plane is the constant 1 (an orthographic view), q is exactly 1.0 and dividing by it
//             changes no bit, so the division is skipped.
//   colour    the same functions as the reference path on the same floats: texture_hooks.h's
//             lookup (through Sampler2D, which gives sampleTexture's bits) and environment, then
//             floatToColorByte and one store.
#include "fragment/block_kernels.h"

#include <array>
#include <bit>
#include <cstring>
#include <optional>

#include "core/context.h"
#include "fragment/color_conversion.h"
#include "glass/raster/triangle.h"
#include "texture/texture_environment.h"
#include "texture/texture_hooks.h"
#include "texture/sampler_2d.h"
#include "vertex/varyings.h"

namespace glass::gl {
namespace {

constexpr int kSize = raster::CoveredBlock::kSize;

int firstBit(unsigned mask) { return std::countr_zero(mask); }
int lastBit(unsigned mask) { return std::bit_width(mask) - 1; }

// The perspective-correct values of the varyings `Slots` at the pixel centres of one block,
// a row at a time: the column parts once per block, the row parts once per row, then the values
// of the row from its first to its last covered column (the uncovered columns between too:
// loops without branches the compiler can vectorise; their values are never read).
template <int... Slots>
class BlockVaryings {
 public:
  static constexpr int kCount = sizeof...(Slots);

  BlockVaryings(const raster::AttributePlanes& planes, const raster::CoveredBlock& block)
      : planes_(planes), rowY0_(block.by + 0.5) {
    constexpr int slots[kCount] = {Slots...};
    unitQ_ = planes.invW0 == 1.0 && planes.invWdx == 0.0 && planes.invWdy == 0.0;
    unsigned columns = 0;
    for (const uint8_t mask : block.rowMask) columns |= mask;
    const double columnX0 = block.bx + 0.5;
    for (int i = firstBit(columns); i <= lastBit(columns); ++i) {
      const double x = columnX0 + i;
      qColumn_[i] = planes.invW0 + planes.invWdx * x;
      for (int n = 0; n < kCount; ++n) pColumn_[n][i] = planes.a0[slots[n]] + planes.dx[slots[n]] * x;
    }
  }

  // Computes the values of row j, whose covered columns are the bits of `mask` (not 0); value(n, i)
  // then reads them.
  void computeRow(int j, unsigned mask) {
    constexpr int slots[kCount] = {Slots...};
    const int first = firstBit(mask), last = lastBit(mask);
    const double y = rowY0_ + j;
    const double qRow = planes_.invWdy * y;
    double q[kSize];
    for (int i = first; i <= last; ++i) q[i] = qColumn_[i] + qRow;
    for (int n = 0; n < kCount; ++n) {
      const double pRow = planes_.dy[slots[n]] * y;
      if (unitQ_) {
        for (int i = first; i <= last; ++i) values_[n][i] = static_cast<float>(pColumn_[n][i] + pRow);
      } else {
        for (int i = first; i <= last; ++i)
          values_[n][i] = static_cast<float>((pColumn_[n][i] + pRow) / q[i]);
      }
    }
  }

  float value(int n, int i) const { return values_[n][i]; }
  // Values of varying n at columns 4 * quarter .. 4 * quarter + 3 (any of them, once computed
  // for the row; columns outside the row's run hold earlier or zero values, never read as
  // pixels).
  ColorLanes lanes(int n, int quarter) const {
    ColorLanes result;
    std::memcpy(&result, &values_[n][4 * quarter], sizeof result);
    return result;
  }

 private:
  const raster::AttributePlanes& planes_;
  double rowY0_;
  bool unitQ_;
  double qColumn_[kSize];
  double pColumn_[kCount > 0 ? kCount : 1][kSize];
  float values_[kCount > 0 ? kCount : 1][kSize] = {};
};

// The per-block constants of texturing by singleTexture2D (texture_hooks.h), and one lambda per
// 2x2 quad, computed by the first covered pixel of the quad that needs it. A block's rows span at
// most five quad rows (pixelQuadOf pairs rows from the top of the window, which an odd window
// height puts out of step with the blocks).
class QuadTexturing {
 public:
  QuadTexturing(const Context& ctx, const raster::TriangleSetup& setup, int by)
      : ctx_(ctx),
        planes_(setup.planes),
        texture_(ctx.texture.units[0].activeTexture()),
        env_(ctx.texture.units[0].env),
        height_(ctx.framebuffer.height()),
        firstQuadRow_(quadRow(by + kSize - 1)) {
    if (texture_ != nullptr) {
      sampler_.emplace(*texture_);
      base_ = texture_->baseImage().base;
      needsLambda_ = needsLevelOfDetail(*texture_);
    }
    for (auto& row : known_) row.fill(false);
  }

  // Replaces color by the textured colour at pixel (x, y) with texture coordinates (s, t, q).
  void apply(int x, int y, float s, float t, float q, float color[4]) {
    if (texture_ == nullptr) return;  // the unit is off (spec 3.8.15)
    const float sq = s / q, tq = t / q;
    float texel[4];
    if (needsLambda_) {
      const int row = quadRow(y) - firstQuadRow_, column = (x >> 1) & 3;
      if (!known_[row][column]) {
        lambda_[row][column] =
            quadLevelOfDetail(ctx_, *texture_, varying::kTexCoord, env_.lodBias, planes_, x, y);
        known_[row][column] = true;
      }
      sampler_->sample(sq, tq, lambda_[row][column], texel);
    } else {
      sampler_->sampleMagnified(sq, tq, texel);
    }
    applyTextureEnvironment(env_.mode, base_, texel, env_.color, color);
  }

 private:
  int quadRow(int y) const { return (height_ - 1 - y) >> 1; }

  const Context& ctx_;
  const raster::AttributePlanes& planes_;
  const TextureObject* texture_;
  const TextureEnvironment& env_;
  std::optional<Sampler2D> sampler_;  // texture_'s lookups, prepared once per block
  BaseFormat base_ = BaseFormat::RGBA;
  int height_, firstQuadRow_;
  bool needsLambda_ = false;
  std::array<std::array<bool, 4>, 5> known_;
  float lambda_[5][4];
};

// Without texturing: nothing to do.
struct NoTexturing {
  NoTexturing(const Context&, const raster::TriangleSetup&, int) {}
};

// The varyings a kernel interpolates and what it does for texturing.
template <KernelTexturing kTexturing>
struct TexturingStage;
template <>
struct TexturingStage<KernelTexturing::None> {
  using Varyings = BlockVaryings<0, 1, 2, 3>;  // the primary colour
  using Texturing = NoTexturing;
};
template <>
struct TexturingStage<KernelTexturing::Single2D> {
  // The primary colour, then s, t and q of unit 0 (r plays no part in a 2D lookup).
  using Varyings = BlockVaryings<0, 1, 2, 3, varying::kTexCoord, varying::kTexCoord + 1,
                                 varying::kTexCoord + 3>;
  using Texturing = QuadTexturing;
};

// Stores words[i] as the 4 bytes at row + 4 i for each bit i of mask (a depth value or an RGBA8
// pixel): a covered run without gaps (most rows) is one copy.
void storeCoveredWords(void* row, const uint32_t* words, unsigned mask) {
  auto* bytes = static_cast<uint8_t*>(row);
  const int first = firstBit(mask), last = lastBit(mask);
  if (mask >> first == (2u << (last - first)) - 1u) {
    std::memcpy(bytes + 4 * first, words + first, 4 * static_cast<size_t>(last - first + 1));
    return;
  }
  for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
    const int i = std::countr_zero(rest);
    std::memcpy(bytes + 4 * i, words + i, 4);
  }
}

template <bool kWriteDepth, bool kWriteColor, KernelTexturing kTexturing>
void shadeBlock(Context& ctx, const raster::TriangleSetup& setup, const raster::CoveredBlock& block) {
  raster::Framebuffer& fb = ctx.framebuffer;
  const int bx = block.bx, by = block.by;
  if constexpr (kWriteDepth) {
    for (int j = 0; j < kSize; ++j) {
      if (block.rowMask[j] != 0)
        storeCoveredWords(fb.depthAt(bx, by + j), block.depth[j], block.rowMask[j]);
    }
  }
  if constexpr (kWriteColor) {
    typename TexturingStage<kTexturing>::Varyings varyings(setup.planes, block);
    [[maybe_unused]] typename TexturingStage<kTexturing>::Texturing texturing(ctx, setup, by);
    for (int j = 0; j < kSize; ++j) {
      const unsigned mask = block.rowMask[j];
      if (mask == 0) continue;
      varyings.computeRow(j, mask);
      auto colorWord = [&](int i) {
        float color[4] = {varyings.value(0, i), varyings.value(1, i), varyings.value(2, i),
                          varyings.value(3, i)};
        if constexpr (kTexturing == KernelTexturing::Single2D) {
          texturing.apply(bx + i, by + j, varyings.value(4, i), varyings.value(5, i),
                          varyings.value(6, i), color);
        }
        return packColorBytes(floatToColorByte(color[0]), floatToColorByte(color[1]),
                              floatToColorByte(color[2]), floatToColorByte(color[3]));
      };
      uint32_t words[kSize];
      if constexpr (kTexturing == KernelTexturing::None) {
        // Four columns at a time, covered or not: the same conversion as colorWord's.
        for (int quarter = 0; quarter < kSize / 4; ++quarter) {
          const ColorWordLanes packed = packColorByteLanes(
              floatToColorByteLanes(varyings.lanes(0, quarter)),
              floatToColorByteLanes(varyings.lanes(1, quarter)),
              floatToColorByteLanes(varyings.lanes(2, quarter)),
              floatToColorByteLanes(varyings.lanes(3, quarter)));
          std::memcpy(&words[4 * quarter], &packed, sizeof packed);
        }
      } else {
        for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
          const int i = std::countr_zero(rest);
          words[i] = colorWord(i);
        }
      }
      storeCoveredWords(fb.colorAt(bx, by + j), words, mask);
    }
  }
}

// Every combination of the key, indexed as kernelIndex() below.
template <int kIndex>
constexpr BlockKernel kernelAt() {
  constexpr bool writeDepth = kIndex & 1, writeColor = kIndex & 2;
  constexpr KernelTexturing texturing = (kIndex & 4) ? KernelTexturing::Single2D : KernelTexturing::None;
  return &shadeBlock<writeDepth, writeColor, texturing>;
}
constexpr BlockKernel kKernels[8] = {kernelAt<0>(), kernelAt<1>(), kernelAt<2>(), kernelAt<3>(),
                                     kernelAt<4>(), kernelAt<5>(), kernelAt<6>(), kernelAt<7>()};

int kernelIndex(const BlockKernelKey& key) {
  const bool textured = key.writeColor && key.texturing == KernelTexturing::Single2D;
  return (key.writeDepth ? 1 : 0) | (key.writeColor ? 2 : 0) | (textured ? 4 : 0);
}

}  // namespace

BlockKernel blockKernelFor(const BlockKernelKey& key) { return kKernels[kernelIndex(key)]; }

}  // namespace glass::gl
