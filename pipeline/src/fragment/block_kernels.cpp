// The kernels of block_kernels.h: one template, specialised by the key, compiled once for each
// SIMD target (hwy/foreach_target.h re-includes this file per target); blockKernelFor takes the
// copy of the target the processor supports best, or of the one GLASS_SIMD_TARGET names
// (core/fast_paths.h, core/simd_dispatch.h).
//
// Equality with the reference path, value by value:
//   depth     the triangle walk computed it; the reference path's depth test after the early
//             test passes for the same fragments (the stored value has not changed in between:
//             a block holds each pixel once), so the kernel only stores it.
//   stencil   with the stencil test on, the kernel tests each covered pixel before shading, a
//             row at a time, with the reference path's function worked lane by lane
//             (stencil_depth_rows-inl.h: the same comparisons and stencil operations on the
//             same values); a block holds each pixel once, so testing all of them first and then
//             shading the ones that passed gives what testing and shading one fragment after
//             another gives.
//   varyings  the reference path (emitBlockFragments, rasterizer/src/triangle_rasterize.cpp)
//             computes float((p_column + p_row) * (1 / (q_column + q_row))) with p_column =
//             a0 + dx x, p_row = dy y, q_column = invW0 + invWdx x, q_row = invWdy y at the
//             pixel centre; BlockVaryings does exactly that, for the slots the key needs only, a
//             row of columns per vector operation, the reciprocal once per row for all slots.
//             When the 1/w plane is the constant 1 (an orthographic view), q is exactly 1.0,
//             and so is its reciprocal, which is then not computed.
//   colour    the same functions as the reference path on the same floats: texture_hooks.h's
//             lookup (through Sampler2D, which gives sampleTexture's bits) and environment, then
//             floatToColorByte (here on a row of pixels at a time) and one store, or, when
//             blending is on, blend()'s bytes with the stored pixels for a row at a time
//             (blend_rows.h); without alpha bitplanes, alpha 255 ORed into what is stored, as
//             the reference path sets it.
//   coverage  an antialiased line's or point's (primitive/smooth_coverage.h): the filter the
//             reference path puts before the fragment stage (CoverageFilter) computes it from
//             each pixel centre and drops a point's pixels of negative coverage before any
//             test; the kernel does both first (smooth_coverage_rows-inl.h, the same operations
//             lane by lane) and multiplies the alpha after fog, where processFragments does.
//
// Equality between targets: every vector operation here is one IEEE operation per lane (add,
// multiply, exact division, conversion with round-to-nearest), which gives the same bits at any
// vector width. Multiplies and adds stay separate (no MulAdd, which fuses on targets with FMA, and
// -ffp-contract=off keeps the compiler from fusing them); no approximate reciprocal. The test
// image_simd_targets renders every image-test program with each target and compares the bytes.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fragment/block_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <array>
#include <bit>
#include <cstring>
#include <optional>
#include <utility>

#include "core/context.h"
#include "core/simd_dispatch.h"
#include "fragment/block_kernels.h"
#include "fragment/blend_rows.h"
#include "fragment/stencil_depth_rows-inl.h"
#include "fragment/stencil_depth_tests.h"
#include "fragment/color_conversion.h"
#include "fragment/color_packing-inl.h"
#include "fragment/covered_pixels.h"
#include "fragment/fog_hooks.h"
#include "fragment/fog_state.h"
#include "glass/raster/triangle.h"
#include "primitive/smooth_coverage.h"
#include "primitive/smooth_coverage_rows-inl.h"
#include "texture/level_of_detail-inl.h"
#include "texture/row_sampler_2d-inl.h"
#include "texture/sampler_2d.h"
#include "texture/texture_environment.h"
#include "texture/texture_hooks.h"
#include "vertex/varyings.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

constexpr int kSize = raster::CoveredBlock::kSize;
// A block row's eight columns: one to four vectors of doubles, depending on the target.
using RowDoubles = hn::CappedTag<double, kSize>;
using RowFloats = hn::CappedTag<float, kSize>;


// The perspective-correct values of the varyings `Slots` at the pixel centres of one block,
// a row at a time: the column parts once per block, the row parts once per row, then the values
// of all eight columns of the row (covered or not: a few vectors without branches; the values
// of uncovered columns are never read).
template <int... Slots>
class BlockVaryings {
 public:
  static constexpr int kCount = sizeof...(Slots);

  BlockVaryings(const raster::AttributePlanes& planes, const raster::CoveredBlock& block)
      : planes_(planes), rowY0_(block.by + 0.5) {
    constexpr int slots[kCount] = {Slots...};
    unitQ_ = planes.invW0 == 1.0 && planes.invWdx == 0.0 && planes.invWdy == 0.0;
    const double columnX0 = block.bx + 0.5;
    for (int i = 0; i < kSize; ++i) {
      const double x = columnX0 + i;
      qColumn_[i] = planes.invW0 + planes.invWdx * x;
      for (int n = 0; n < kCount; ++n) pColumn_[n][i] = planes.a0[slots[n]] + planes.dx[slots[n]] * x;
    }
  }

  // Computes the values of row j; row(n) then reads them.
  void computeRow(int j) {
    constexpr int slots[kCount] = {Slots...};
    const RowDoubles d;
    const hn::Rebind<float, RowDoubles> f;
    const double y = rowY0_ + j;
    const int lanes = static_cast<int>(hn::Lanes(d));
    // 1 / q, or exactly 1 when q is (the products below then change no bit).
    alignas(64) double inverseQ[kSize];
    const auto qRow = hn::Set(d, planes_.invWdy * y), one = hn::Set(d, 1.0);
    for (int i = 0; i < kSize; i += lanes)
      hn::Store(unitQ_ ? one : hn::Div(one, hn::Add(hn::Load(d, &qColumn_[i]), qRow)), d, &inverseQ[i]);
    for (int n = 0; n < kCount; ++n) {
      const auto pRow = hn::Set(d, planes_.dy[slots[n]] * y);
      for (int i = 0; i < kSize; i += lanes) {
        const auto value = hn::Mul(hn::Add(hn::Load(d, &pColumn_[n][i]), pRow), hn::Load(d, &inverseQ[i]));
        hn::Store(hn::DemoteTo(f, value), f, &values_[n][i]);
      }
    }
  }

  const float* row(int n) const { return values_[n]; }
  // The values of the row as rows of kSize floats, for a stage that changes them in place (the
  // colour's four rows when they come first: texturing and fog).
  float (*rows())[kSize] { return values_; }

 private:
  const raster::AttributePlanes& planes_;
  double rowY0_;
  bool unitQ_;
  alignas(64) double qColumn_[kSize];
  alignas(64) double pColumn_[kCount][kSize];
  alignas(64) float values_[kCount][kSize] = {};
};

// floatToColorByte and packColorBytes (color_conversion.h) on the eight pixels of a row, whose
// components are in the arrays red .. alpha: the same operations lane by lane.
void packRowColors(const float* red, const float* green, const float* blue, const float* alpha,
                   uint32_t words[kSize]) {
  const RowFloats f;
  for (int i = 0; i < kSize; i += static_cast<int>(hn::Lanes(f)))
    color_packing::packColorVector(f, red + i, green + i, blue + i, alpha + i, words + i);
}

// quotient[i] = numerator[i] / denominator[i] for the eight columns of a row, in float (the
// reference's s / q and t / q of a texture lookup).
void divideRow(const float* numerator, const float* denominator, float quotient[kSize]) {
  const RowFloats f;
  for (int i = 0; i < kSize; i += static_cast<int>(hn::Lanes(f)))
    hn::Store(hn::Div(hn::Load(f, numerator + i), hn::Load(f, denominator + i)), f, quotient + i);
}

// Texturing by singleTexture2D (texture_hooks.h) for one block, with what the draw prepared
// (KernelTexture), and one lambda per 2x2 quad. A block's rows span at most five quad rows
// (pixelQuadOf pairs rows from the top of the window, and a block starts at its triangle's first
// row, so the pairs need not line up with the block), each of four quads. When lambda is needed, the quads of every quad row with
// pixels to shade get their rho^2, lambda and levels first, all rows together
// (textureLevelOfDetail's operations, one quad per lane): each row's chain of dependent
// operations (two divisions, the log2 series) then overlaps the others' instead of waiting
// between the rows' texture lookups.
class QuadTexturing {
 public:
  // rowMask: the pixels of the block that will be shaded (applyRow reads no other row).
  QuadTexturing(const Context& ctx, const KernelTexture& texture, const raster::TriangleSetup& setup,
                int bx, int by, const uint8_t rowMask[kSize])
      : planes_(setup.planes),
        t_(texture),
        height_(ctx.framebuffer.height()),
        firstQuadRow_(quadRow(by + kSize - 1)),
        quadX0_(bx + 0.5) {
    if (active() && t_.needsLambda) chooseLevels(by, rowMask);
  }

  bool active() const { return t_.sampler.has_value(); }  // the unit is on (spec 3.8.15)

  // Replaces the colours of the pixels of `mask` in the block's row y (pixel i in column i) by
  // their textured colours, with projected texture coordinates (s/q, t/q) = (sq[i], tq[i]).
  void applyRow(int y, unsigned mask, const float* sq, const float* tq, float color[4][kSize]) {
    // Pixels 2k and 2k + 1 share quad k (blocks start at even columns: quads do not straddle).
    static_assert(row_sampler::kRowQuads == kLevelOfDetailQuads);
    const Sampler2D::LevelChoice* quadChoice = t_.needsLambda ? rowLevels(y) : t_.magnified;
    alignas(64) float texel[4][kSize] = {};  // pixels outside mask stay 0
    row_sampler::sampleRow(*t_.sampler, sq, tq, quadChoice, mask, texel);
    applyEnvironmentRow(texel, mask, color);
  }

 private:
  int quadRow(int y) const { return (height_ - 1 - y) >> 1; }

  // The levels the four 2x2 quads of row y read, from their lambdas.
  const Sampler2D::LevelChoice* rowLevels(int y) const { return choice_[quadRow(y) - firstQuadRow_]; }

  // applyTextureEnvironment on the pixels of mask: REPLACE and MODULATE a row at a time (the
  // same single operation per component), the other modes pixel by pixel.
  void applyEnvironmentRow(const float texel[4][kSize], unsigned mask, float color[4][kSize]) const {
    const bool hasColor = baseFormatHasColor(t_.base), hasAlpha = baseFormatHasAlpha(t_.base);
    const TextureEnvironment& env = *t_.env;
    if (env.mode == GL_REPLACE || env.mode == GL_MODULATE) {
      const RowFloats f;
      for (int c = 0; c < 4; ++c) {
        if (!(c < 3 ? hasColor : hasAlpha)) continue;
        for (int i = 0; i < kSize; i += static_cast<int>(hn::Lanes(f))) {
          const auto t = hn::Load(f, texel[c] + i);
          hn::Store(env.mode == GL_REPLACE ? t : hn::Mul(hn::Load(f, color[c] + i), t), f, color[c] + i);
        }
      }
      return;
    }
    for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
      const int i = std::countr_zero(rest);
      const float pixelTexel[4] = {texel[0][i], texel[1][i], texel[2][i], texel[3][i]};
      float pixel[4] = {color[0][i], color[1][i], color[2][i], color[3][i]};
      applyTextureEnvironment(env.mode, t_.base, pixelTexel, env.color, pixel);
      for (int c = 0; c < 4; ++c) color[c][i] = pixel[c];
    }
  }

  // The levels of the four quads of each quad row that holds a row of rowMask: rho^2, then
  // lambda (textureLevelOfDetail's, in lanes), then the choice of levels, each step for all those
  // rows before the next, well before applyRow reads them (a choice read right after its fields
  // were written would wait for the stores).
  void chooseLevels(int by, const uint8_t rowMask[kSize]) {
    constexpr int kQuadRows = 5;
    bool needed[kQuadRows] = {};
    for (int j = 0; j < kSize; ++j)
      if (rowMask[j] != 0) needed[quadRow(by + j) - firstQuadRow_] = true;
    alignas(32) double rhoSquared[kQuadRows][level_of_detail::kQuads];
    for (int row = 0; row < kQuadRows; ++row)
      if (needed[row]) scaleFactorsSquared(row, rhoSquared[row]);
    float lambda[kQuadRows][level_of_detail::kQuads];
    for (int row = 0; row < kQuadRows; ++row) {
      if (needed[row])
        level_of_detail::levelsOfDetail(rhoSquared[row], t_.minLod, t_.maxLod, t_.lodBias, lambda[row]);
    }
    for (int row = 0; row < kQuadRows; ++row) {
      if (!needed[row]) continue;
      for (int k = 0; k < level_of_detail::kQuads; ++k) choice_[row][k] = t_.sampler->choose(lambda[row][k]);
    }
  }

  // rho^2 of the four quads of quad row `row` as quadLevelOfDetail computes it for a 2D texture
  // (quadTexCoordDifferences and textureScaleFactorSquared of texture_lod.h), the same
  // operations in the same order, one quad per lane.
  void scaleFactorsSquared(int row, double rhoSquared[level_of_detail::kQuads]) const {
    const hn::CappedTag<double, 4> d;
    constexpr int s = varying::kTexCoord, t = varying::kTexCoord + 1, q = varying::kTexCoord + 3;
    const raster::AttributePlanes& p = planes_;
    const double top = height_ - 1 - 2 * (firstQuadRow_ + row);  // pixelQuadOf's upper row
    const double y = top + 0.5;
    const auto bx = hn::Set(d, p.dx[q]), by = hn::Set(d, p.dy[q]);
    const auto one = hn::Set(d, 1.0);
    const auto width = hn::Set(d, static_cast<double>(t_.baseWidth));
    const auto height = hn::Set(d, static_cast<double>(t_.baseHeight));
    auto plane = [&](int v, auto x) {  // a0 + dx x + dy y, left to right
      return hn::Add(hn::Add(hn::Set(d, p.a0[v]), hn::Mul(hn::Set(d, p.dx[v]), x)),
                     hn::Set(d, p.dy[v] * y));
    };
    for (int k = 0; k < level_of_detail::kQuads; k += static_cast<int>(hn::Lanes(d))) {
      // The upper-left pixel centres of quads k, k + 1, ...: x = left + 0.5, left = bx + 2 k.
      alignas(32) double lefts[4];
      for (int i = 0; i < 4; ++i) lefts[i] = quadX0_ + 2 * (k + i);
      const auto x = hn::Load(d, lefts);
      const auto a = plane(s, x), b = plane(q, x), c = plane(t, x);
      const auto inverseRight = hn::Div(one, hn::Mul(b, hn::Add(b, bx)));
      const auto inverseLower = hn::Div(one, hn::Mul(b, hn::Sub(b, by)));
      // (slope b - value along) inverse: a difference of quadTexCoordDifferences.
      auto difference = [&](const auto& value, const auto& along, double slope, const auto& inverse) {
        return hn::Mul(hn::Sub(hn::Mul(hn::Set(d, slope), b), hn::Mul(value, along)), inverse);
      };
      const auto dudx = hn::Mul(difference(a, bx, p.dx[s], inverseRight), width);
      const auto dudy = hn::Mul(difference(a, by, p.dy[s], inverseLower), width);
      const auto dvdx = hn::Mul(difference(c, bx, p.dx[t], inverseRight), height);
      const auto dvdy = hn::Mul(difference(c, by, p.dy[t], inverseLower), height);
      const auto alongX = hn::Add(hn::Mul(dudx, dudx), hn::Mul(dvdx, dvdx));
      const auto alongY = hn::Add(hn::Mul(dudy, dudy), hn::Mul(dvdy, dvdy));
      // std::max(alongX, alongY): alongY only when alongX < alongY (NaN keeps alongX).
      hn::Store(hn::IfThenElse(hn::Lt(alongX, alongY), alongY, alongX), d, rhoSquared + k);
    }
  }

  const raster::AttributePlanes& planes_;
  const KernelTexture& t_;  // the draw's texture
  int height_, firstQuadRow_;
  double quadX0_;
  Sampler2D::LevelChoice choice_[5][level_of_detail::kQuads];
};

// Without texturing: nothing to do.
struct NoTexturing {
  NoTexturing(const Context&, const KernelTexture&, const raster::TriangleSetup&, int, int, const uint8_t*) {}
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

// Stores words[i] as the 4 bytes at row + 4 i for each bit i of mask.
void storeCoveredWords(void* row, const uint32_t* words, unsigned mask) { copyCoveredWords(row, words, mask); }

// words[i] |= alpha for the eight pixels of a row (KernelPixelOps::storedAlpha). Nothing to do
// with alpha bitplanes (alpha 0): the words, just stored, are not loaded and stored again.
void orRowWords(uint32_t words[kSize], uint32_t alpha) {
  if (alpha == 0) return;
  for (int i = 0; i < kSize; ++i) words[i] |= alpha;
}

// The stencil and depth tests and their writes on each pixel of rowMask, a row at a time, each
// pixel as the reference path's function tests it (stencil_depth_rows-inl.h); rowMask keeps, per
// row, the pixels that passed both.
void testStencilAndDepthOfBlock(raster::Framebuffer& fb, const StencilDepthSettings& tests,
                                const raster::CoveredBlock& block, uint8_t rowMask[kSize]) {
  static_assert(stencil_depth_rows::kRowPixels == kSize);
  for (int j = 0; j < kSize; ++j) {
    if (rowMask[j] == 0) continue;
    const int y = block.by + j;
    uint8_t* stencil = tests.stencilTest ? fb.stencilAt(block.bx, y) : nullptr;
    uint32_t* depth = tests.depthTest ? fb.depthAt(block.bx, y) : nullptr;
    rowMask[j] = static_cast<uint8_t>(
        stencil_depth_rows::testStencilAndDepthRow(tests, stencil, depth, block.depth[j], rowMask[j]));
  }
}

// How the fragments of an antialiased shape are weighed (smooth_coverage_rows-inl.h).
template <KernelCoverage kCoverage>
struct CoverageStage;
template <>
struct CoverageStage<KernelCoverage::SmoothLine> {
  using Shape = SmoothLineCoverage;
  using Rows = smooth_coverage_rows::LineRows<kSize>;
};
template <>
struct CoverageStage<KernelCoverage::SmoothPoint> {
  using Shape = SmoothPointCoverage;
  using Rows = smooth_coverage_rows::PointRows<kSize>;
};

// The coverage of the pixels of rowMask for the shape in the triangle's payload, as the
// reference path's CoverageFilter computes it; the pixels of negative coverage (outside a
// point's disc) leave rowMask, as the filter drops them before any test.
template <KernelCoverage kCoverage>
void weighBlock(const float* payload, const raster::CoveredBlock& block, uint8_t rowMask[kSize],
                float coverage[kSize][kSize]) {
  using Stage = CoverageStage<kCoverage>;
  typename Stage::Shape shape;
  std::memcpy(static_cast<void*>(&shape), payload, sizeof shape);  // trivially copyable floats
  const typename Stage::Rows rows(shape);
  const smooth_coverage_rows::ColumnCentres<kSize> centres(block.bx);
  for (int j = 0; j < kSize; ++j) {
    if (rowMask[j] == 0) continue;
    rows.row(centres.x, static_cast<float>(block.by + j) + 0.5f, coverage[j]);
    // A line's coverage is a product of clamped values and a positive factor, never below 0
    // (at worst -0 or NaN, which the filter keeps too): only a point's pixels can be dropped.
    if constexpr (kCoverage == KernelCoverage::SmoothPoint) {
      unsigned mask = rowMask[j];
      for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
        const int i = std::countr_zero(rest);
        if (coverage[j][i] < 0.0f) mask &= ~(1u << i);
      }
      rowMask[j] = static_cast<uint8_t>(mask);
    }
  }
}

// color[3][i] *= coverage[i] for the row's pixels (spec 3.11), as the reference path does after fog.
void weighAlphaRow(const float* coverage, float color[4][kSize]) {
  const RowFloats f;
  for (int i = 0; i < kSize; i += static_cast<int>(hn::Lanes(f)))
    hn::Store(hn::Mul(hn::Load(f, color[3] + i), hn::Load(f, coverage + i)), f, color[3] + i);
}

// Blends the colours words[i] (RGBA8, as packColorBytes lays them out) of the pixels of mask
// into the colour buffer's row, the row's pixels at once (blend_rows.h, blend()'s bytes); the
// buffer's pixels outside mask are neither read nor written.
void blendCoveredWords(const KernelPixelOps& ops, uint8_t* row, const uint32_t* words, unsigned mask) {
  alignas(64) uint32_t destination[kSize] = {}, blended[kSize];
  copyCoveredWords(destination, row, mask);
  ops.blendRow(ops.blendSettings, words, destination, blended);
  orRowWords(blended, ops.storedAlpha);
  storeCoveredWords(row, blended, mask);
}

// The fog of fog_hooks.h's applyFog on the pixels of mask, whose fog coordinates are c[i]: the
// same function for the factor and the same expression for each colour component.
void applyFogRow(const FogState& fog, const float* c, unsigned mask, float color[4][kSize]) {
  for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
    const int i = std::countr_zero(rest);
    const float f = fogFactor(fog, c[i]);
    for (int k = 0; k < 3; ++k) color[k][i] = f * color[k][i] + (1.0f - f) * fog.color[k];
  }
}

template <bool kWriteDepth, bool kWriteColor, KernelTexturing kTexturing, bool kFog, KernelCoverage kCoverage>
void shadeBlock(Context& ctx, const KernelPixelOps& ops, const KernelTexture& texture, [[maybe_unused]] const FogState& fog,
                const raster::TriangleSetup& setup, const raster::CoveredBlock& block) {
  raster::Framebuffer& fb = ctx.framebuffer;
  const int bx = block.bx, by = block.by;
  uint8_t rowMask[kSize];  // the pixels to shade
  std::memcpy(rowMask, block.rowMask, sizeof rowMask);
  [[maybe_unused]] alignas(64) float coverage[kSize][kSize];
  if constexpr (kCoverage != KernelCoverage::None) weighBlock<kCoverage>(setup.payload, block, rowMask, coverage);
  if (ops.tests.stencilTest) {
    testStencilAndDepthOfBlock(fb, ops.tests, block, rowMask);
  } else {
    if constexpr (kWriteDepth) {
      for (int j = 0; j < kSize; ++j) {
        if (rowMask[j] != 0) storeCoveredWords(fb.depthAt(bx, by + j), block.depth[j], rowMask[j]);
      }
    }
  }
  if constexpr (kWriteColor) {
    unsigned any = 0;
    for (const uint8_t mask : rowMask) any |= mask;
    if (any == 0) return;
    typename TexturingStage<kTexturing>::Varyings varyings(setup.planes, block);
    using Texturing = typename TexturingStage<kTexturing>::Texturing;
    [[maybe_unused]] Texturing texturing(ctx, texture, setup, bx, by, rowMask);
    using FogVaryings = BlockVaryings<varying::kFogCoordinate>;
    std::optional<FogVaryings> fogCoordinate;
    if constexpr (kFog) fogCoordinate.emplace(setup.planes, block);
    for (int j = 0; j < kSize; ++j) {
      const unsigned mask = rowMask[j];
      if (mask == 0) continue;
      varyings.computeRow(j);
      float(*color)[kSize] = varyings.rows();  // the primary colour, textured and fogged in place
      if constexpr (kTexturing != KernelTexturing::None) {
        if (texturing.active()) {
          alignas(64) float sq[kSize], tq[kSize];
          divideRow(varyings.row(4), varyings.row(6), sq);
          divideRow(varyings.row(5), varyings.row(6), tq);
          texturing.applyRow(by + j, mask, sq, tq, color);
        }
      }
      if constexpr (kFog) {
        fogCoordinate->computeRow(j);
        applyFogRow(fog, fogCoordinate->row(0), mask, color);
      }
      if constexpr (kCoverage != KernelCoverage::None) weighAlphaRow(coverage[j], color);
      alignas(64) uint32_t words[kSize];
      packRowColors(color[0], color[1], color[2], color[3], words);
      if (ops.blend) {
        blendCoveredWords(ops, fb.colorAt(bx, by + j), words, mask);
      } else {
        orRowWords(words, ops.storedAlpha);
        storeCoveredWords(fb.colorAt(bx, by + j), words, mask);
      }
    }
  }
}

// Every combination of the key, indexed as kernelIndex() below.
template <int kIndex>
constexpr BlockKernel kernelAt() {
  constexpr bool writeDepth = kIndex & 1, writeColor = kIndex & 2;
  constexpr KernelTexturing texturing = (kIndex & 4) ? KernelTexturing::Single2D : KernelTexturing::None;
  constexpr bool fog = kIndex & 8;
  constexpr auto coverage = static_cast<KernelCoverage>(kIndex >> 4);
  return &shadeBlock<writeDepth, writeColor, texturing, fog, coverage>;
}
template <int... kIndices>
constexpr std::array<BlockKernel, sizeof...(kIndices)> kernelTable(std::integer_sequence<int, kIndices...>) {
  return {kernelAt<kIndices>()...};
}
constexpr auto kKernels = kernelTable(std::make_integer_sequence<int, 16 * kKernelCoverageCount>());

}  // namespace

// This target's kernel number `index` (kernelIndex below).
BlockKernel BlockKernelAt(int index) { return kKernels[index]; }

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {
namespace {

int kernelIndex(const BlockKernelKey& key) {
  // Texturing and fog matter only when colour is written.
  const bool textured = key.writeColor && key.texturing == KernelTexturing::Single2D;
  const bool fog = key.writeColor && key.fog;
  return (key.writeDepth ? 1 : 0) | (key.writeColor ? 2 : 0) | (textured ? 4 : 0) | (fog ? 8 : 0) |
         (static_cast<int>(key.coverage) << 4);
}

}  // namespace

constexpr SimdFunctions<BlockKernel (*)(int)> kBlockKernelAt = GLASS_SIMD_FUNCTIONS(BlockKernelAt);

BlockKernel blockKernelFor(const BlockKernelKey& key) {
  return chosenSimdFunction(kBlockKernelAt)(kernelIndex(key));
}

}  // namespace glass::gl
#endif  // HWY_ONCE
