// A complete 2D colour texture prepared for the lookups of one draw (the fragment kernels of
// fragment/block_kernels.h): sampleTexture and sampleTextureMagnified (texture_sampler.h) for
// the case that dominates drawing, with every state check done once in the constructor instead
// of once per lookup, and everything inline so that the kernel's loop makes no call (forced:
// the kernels are compiled once per SIMD target, and GCC would otherwise call one out-of-line
// baseline copy from all of them).
//
// The result has the same bits as the reference sampler's: the same texel coordinates and index
// arithmetic (texel_addressing.h) and the same fixed-point filter (texel_filter.h), computed on
// the four components at once.
// The unit test sampler_2d_matches_reference compares the two over filters, wrap modes, sizes
// and coordinates, NaN and huge ones included.
#pragma once

#include <GL/gl.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "texture/texel_addressing.h"
#include "texture/texel_filter.h"
#include "texture/texture_lod.h"
#include "texture/texture_object.h"

namespace glass::gl {

class Sampler2D {
  // The four components of a texel as the four lanes of one vector (GCC and Clang vector
  // extensions, which compile to the target's vector instructions or to scalar code): each lane
  // computes exactly the reference's expression for its component, with one instruction for
  // all four.
  using TexelLanes = float __attribute__((vector_size(16)));
  using FixedLanes = uint32_t __attribute__((vector_size(16)));  // texel_filter's fixed point
  using IntLanes = int32_t __attribute__((vector_size(16)));
  using ShortLanes = int16_t __attribute__((vector_size(16)));
  using ByteLanes = uint8_t __attribute__((vector_size(16)));
  // The four bytes of a texel (or the border's) widened to lanes.
  [[gnu::always_inline]] static FixedLanes texelLanes(const uint8_t* texel) {
    // The four bytes widened by interleaving with zeros, bytes then 16-bit halves (the two
    // unpack instructions of x86-64's SSE2).
    uint32_t word;
    std::memcpy(&word, texel, sizeof word);
    const FixedLanes packed = {word, 0, 0, 0};
    ByteLanes bytes;
    std::memcpy(&bytes, &packed, sizeof bytes);
    const ByteLanes byteHalves = __builtin_shufflevector(bytes, ByteLanes{}, 0, 16, 1, 17, 2, 18, 3,
                                                         19, 4, 20, 5, 21, 6, 22, 7, 23);
    ShortLanes shorts;
    std::memcpy(&shorts, &byteHalves, sizeof shorts);
    const ShortLanes shortHalves = __builtin_shufflevector(shorts, ShortLanes{}, 0, 8, 1, 9, 2, 10, 3, 11);
    FixedLanes lanes;
    std::memcpy(&lanes, &shortHalves, sizeof lanes);
    return lanes;
  }
  // texel_filter::mixTexels and mixFixed on four components at once.
  [[gnu::always_inline]] static FixedLanes mixTexels(FixedLanes t0, FixedLanes t1, uint32_t a) {
    return t0 * (texel_filter::kWeightOne - a) + t1 * a;
  }
  [[gnu::always_inline]] static FixedLanes mixFixed(FixedLanes x0, FixedLanes x1, uint32_t w) {
    return x0 + ((x1 * w) >> 16) - ((x0 * w) >> 16);
  }
  [[gnu::always_inline]] static void storeUnit(FixedLanes fixed, float out[4]) {
    // Through signed lanes (the values are below 2^16): one conversion instruction.
    const TexelLanes unit = __builtin_convertvector((IntLanes)fixed, TexelLanes) *
                            (1.0f / 65280.0f);
    std::memcpy(out, &unit, sizeof unit);
  }

 public:
  // `texture` is complete, its target GL_TEXTURE_2D, its images colour (not depth) images; it
  // must outlive the sampler and not change while the sampler is used.
  explicit Sampler2D(const TextureObject& texture)
      : minFilter_(texture.params.minFilter),
        wrapS_(texture.params.wrapS),
        wrapT_(texture.params.wrapT),
        base_(texture.params.baseLevel),
        last_(texture.lastLevel),
        switchOverPoint_(texture.sampling.switchOverPoint),
        magnifyLinear_(texture.params.magFilter == GL_LINEAR),
        linearWithinLevel_(minFilter_ == GL_LINEAR || minFilter_ == GL_LINEAR_MIPMAP_NEAREST ||
                           minFilter_ == GL_LINEAR_MIPMAP_LINEAR),
        mipmapped_(isMipmapFilter(minFilter_)) {
    const int lastUsed = mipmapped_ ? last_ : base_;
    for (int level = base_; level <= lastUsed; ++level) {
      const TextureImage& image = texture.image(0, level);
      const bool powerOfTwo = (image.width & (image.width - 1)) == 0 &&
                              (image.height & (image.height - 1)) == 0;
      levels_[level] = {image.texels.data(), image.width, image.height,
                        static_cast<float>(image.width), static_cast<float>(image.height),
                        wrapS_ == GL_REPEAT && wrapT_ == GL_REPEAT && powerOfTwo};
    }
    std::memcpy(borderBytes_, texture.sampling.borderBytes, sizeof borderBytes_);
  }

  // The levels a lookup reads and how (sampleTexture's choice, section 3.8.8): level1 alone, or
  // level1 and level2 mixed by weight2 (texel_filter::levelWeight's) when `mixes`; `linear` is
  // the filter within a level.
  struct LevelChoice {
    int level1, level2;
    int weight2;
    bool mixes, linear;
  };
  [[gnu::always_inline]] LevelChoice choose(float lambda) const {
    if (lambda <= switchOverPoint_) return chooseMagnified();
    if (!mipmapped_) return {base_, base_, 0, false, linearWithinLevel_};
    const MipmapLevels m = selectMipmapLevels(lambda, minFilter_, base_, last_);
    const bool mixes = m.level2 != m.level1 && m.weight2 != 0.0f;
    return {m.level1, m.level2, texel_filter::levelWeight(m.weight2), mixes, linearWithinLevel_};
  }
  // The magnification filter's choice (no lambda needed, or lambda <= c).
  LevelChoice chooseMagnified() const { return {base_, base_, 0, false, magnifyLinear_}; }

  // sampleTexture(texture, s, t, lambda, out).
  [[gnu::always_inline]] void sample(float s, float t, float lambda, float out[4]) const {
    sampleChosen(choose(lambda), s, t, out);
  }

  // sampleTextureMagnified(texture, s, t, out).
  [[gnu::always_inline]] void sampleMagnified(float s, float t, float out[4]) const {
    sampleChosen(chooseMagnified(), s, t, out);
  }

  // The lookup at (s, t) from the levels `choice` names.
  [[gnu::always_inline]] void sampleChosen(const LevelChoice& choice, float s, float t, float out[4]) const {
    const FixedLanes first = sampleLevel(levels_[choice.level1], choice.linear, s, t);
    if (!choice.mixes) return storeUnit(first, out);
    const FixedLanes second = sampleLevel(levels_[choice.level2], choice.linear, s, t);
    storeUnit(mixFixed(first, second, static_cast<uint32_t>(choice.weight2)), out);
  }

  struct Level {
    const uint8_t* texels;  // width * height RGBA8 texels, row 0 first
    int width, height;
    float widthF, heightF;
    bool repeatsByMask;  // GL_REPEAT on both axes and power-of-two sides: wrap() is a mask
  };
  // Level n of the texture (n between the base level and the last one sample() reads).
  const Level& level(int n) const { return levels_[n]; }

 private:
  // The filtered texel of one level, in texel_filter's fixed point.
  [[gnu::always_inline]] FixedLanes sampleLevel(const Level& level, bool linear, float s, float t) const {
    return linear ? sampleLinear(level, s, t) : sampleNearest(level, s, t);
  }

  // texelCoordinate(s, size, mode), with the size as a float at hand.
  static float coordinate(float s, int size, float sizeF, GLenum mode) {
    if (mode == GL_CLAMP) s = std::clamp(s, 0.0f, 1.0f);
    return keepInIntRange(s * sizeF, size, mode);
  }

  static const uint8_t* texelAt(const Level& level, int i, int j) {
    return level.texels + 4 * (static_cast<std::ptrdiff_t>(j) * level.width + i);
  }

  FixedLanes sampleNearest(const Level& level, float s, float t) const {
    const float u = coordinate(s, level.width, level.widthF, wrapS_);
    const float v = coordinate(t, level.height, level.heightF, wrapT_);
    const int i = wrapTexelIndex(floorToInt(u), level.width, wrapS_, false);
    const int j = wrapTexelIndex(floorToInt(v), level.height, wrapT_, false);
    const bool inside = i >= 0 && i < level.width && j >= 0 && j < level.height;
    return texelLanes(inside ? texelAt(level, i, j) : borderBytes_) * texel_filter::kWeightOne;
  }

  // Inline for the common case (see repeatsByMask), a call for the others.
  [[gnu::always_inline]] FixedLanes sampleLinear(const Level& level, float s, float t) const {
    if (level.repeatsByMask) {
      // The common case in short: keepInIntRange leaves u and v as they are (below 2^20 in
      // magnitude, not NaN), wrapTexelPair is a mask, and all four texels are inside.
      const float uScaled = s * level.widthF, vScaled = t * level.heightF;
      constexpr float kLimit = 1048576.0f;  // keepInIntRange's
      if (std::fabs(uScaled) < kLimit && std::fabs(vScaled) < kLimit) {
        const int u = texel_filter::fixedCoordinate(uScaled - 0.5f);
        const int v = texel_filter::fixedCoordinate(vScaled - 0.5f);
        const int i0 = texel_filter::wholeTexel(u) & (level.width - 1), i1 = (i0 + 1) & (level.width - 1);
        const int j0 = texel_filter::wholeTexel(v) & (level.height - 1), j1 = (j0 + 1) & (level.height - 1);
        return bilinear(texelAt(level, i0, j0), texelAt(level, i1, j0), texelAt(level, i0, j1),
                        texelAt(level, i1, j1), texel_filter::subtexelWeight(u), texel_filter::subtexelWeight(v));
      }
    }
    return sampleLinearAnyWrap(level, s, t);
  }

  [[gnu::noinline]] FixedLanes sampleLinearAnyWrap(const Level& level, float s, float t) const {
    const int u = texel_filter::fixedCoordinate(coordinate(s, level.width, level.widthF, wrapS_) - 0.5f);
    const int v = texel_filter::fixedCoordinate(coordinate(t, level.height, level.heightF, wrapT_) - 0.5f);
    int i0, i1, j0, j1;
    wrapTexelPair(texel_filter::wholeTexel(u), level.width, wrapS_, &i0, &i1);
    wrapTexelPair(texel_filter::wholeTexel(v), level.height, wrapT_, &j0, &j1);
    // Near a CLAMP or CLAMP_TO_BORDER edge: texels outside the image are the border colour.
    auto texelOrBorder = [&](int i, int j) {
      // Unsigned comparisons test 0 <= index < size at once.
      const bool in = static_cast<unsigned>(i) < static_cast<unsigned>(level.width) &&
                      static_cast<unsigned>(j) < static_cast<unsigned>(level.height);
      return in ? texelAt(level, i, j) : borderBytes_;
    };
    return bilinear(texelOrBorder(i0, j0), texelOrBorder(i1, j0), texelOrBorder(i0, j1), texelOrBorder(i1, j1),
                    texel_filter::subtexelWeight(u), texel_filter::subtexelWeight(v));
  }

  // The LINEAR mix of four texels with subtexel weights a and b (texel_filter.h).
  [[gnu::always_inline]] static FixedLanes bilinear(const uint8_t* t00, const uint8_t* t10, const uint8_t* t01,
                                                    const uint8_t* t11, int a, int b) {
    const uint32_t weightA = static_cast<uint32_t>(a);
    return mixFixed(mixTexels(texelLanes(t00), texelLanes(t10), weightA),
                    mixTexels(texelLanes(t01), texelLanes(t11), weightA),
                    static_cast<uint32_t>(texel_filter::rowWeight(b)));
  }

  GLenum minFilter_, wrapS_, wrapT_;
  int base_, last_;
  float switchOverPoint_;
  bool magnifyLinear_, linearWithinLevel_, mipmapped_;
  Level levels_[kMaxTextureLevels] = {};
  uint8_t borderBytes_[4];  // the border texel
};

}  // namespace glass::gl
