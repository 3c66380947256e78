// Texture lookups for a row of up to eight pixels at once, the row of a fragment kernel's block
// (fragment/block_kernels.h): texel[c][i] is component c of what Sampler2D::sample (or
// sampleMagnified) gives for pixel i, bit for bit.
//
// The common case of textured drawing -- LINEAR filtering within power-of-two GL_REPEAT levels,
// one level or two mixed (GL_LINEAR_MIPMAP_LINEAR) -- runs on vectors of pixels: one lane per
// pixel, the same IEEE operations in the same order as Sampler2D's sampleLinear and bilinear
// (texel coordinate, floor, weights, the four-texel sum left to right, the scale by 1/255, the
// mix of two levels), so every lane gives the scalar result's bits on every SIMD target. The
// pixels of a row may read different levels (a lambda per 2x2 quad): they are taken one level
// pair at a time.
// Pixels outside that case (NEAREST filters, other wrap modes, sides not a power of two,
// coordinates beyond 2^20 texels, NaN) take Sampler2D itself.
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each). The unit test row_sampler_2d_matches_sampler compares it with Sampler2D on every target.
#if defined(GLASS_TEXTURE_ROW_SAMPLER_2D_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_TEXTURE_ROW_SAMPLER_2D_INL_H_
#undef GLASS_TEXTURE_ROW_SAMPLER_2D_INL_H_
#else
#define GLASS_TEXTURE_ROW_SAMPLER_2D_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

#include "texture/sampler_2d.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace row_sampler {

namespace hn = hwy::HWY_NAMESPACE;

constexpr int kRowPixels = 8;
using RowTag = hn::CappedTag<float, kRowPixels>;

// Component c of packed RGBA8 texels (the bytes in memory order R, G, B, A) as floats.
template <int kComponent, class V>
auto componentOf(V words) {
  constexpr int kShift = std::endian::native == std::endian::little ? 8 * kComponent : 24 - 8 * kComponent;
  const RowTag f;
  const hn::RebindToUnsigned<RowTag> u;
  const hn::RebindToSigned<RowTag> i;
  return hn::ConvertTo(f, hn::BitCast(i, hn::And(hn::ShiftRight<kShift>(words), hn::Set(u, 0xFFu))));
}

// The four-texel sum of one component, left to right as in Sampler2D::bilinear, scaled to [0, 1].
template <int kComponent, class VF, class VU>
VF bilinearComponent(const VF (&weight)[4], const VU (&words)[4]) {
  const RowTag f;
  auto sum = hn::Mul(weight[0], componentOf<kComponent>(words[0]));
  sum = hn::Add(sum, hn::Mul(weight[1], componentOf<kComponent>(words[1])));
  sum = hn::Add(sum, hn::Mul(weight[2], componentOf<kComponent>(words[2])));
  sum = hn::Add(sum, hn::Mul(weight[3], componentOf<kComponent>(words[3])));
  return hn::Mul(sum, hn::Set(f, 1.0f / 255.0f));
}

// The texel words at `offsets` (in texels) of an RGBA8 image, one per lane.
template <class VI>
auto texelWords(const uint8_t* texels, VI offsets) {
  const RowTag f;
  const hn::RebindToUnsigned<RowTag> du;
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  // Portable code reads the bytes as bytes.
  alignas(64) int32_t offset[kRowPixels];
  alignas(64) uint32_t words[kRowPixels];
  hn::Store(offsets, hn::RebindToSigned<RowTag>(), offset);
  for (size_t i = 0; i < hn::Lanes(f); ++i)
    std::memcpy(&words[i], texels + 4 * static_cast<std::ptrdiff_t>(offset[i]), sizeof words[i]);
  return hn::Load(du, words);
#else
  // The images are vectors of bytes allocated by operator new, so 4-byte aligned.
  return hn::GatherIndex(du, reinterpret_cast<const uint32_t*>(texels), offsets);
#endif
}

// The words of texels i0 and i0 + 1 of rows j0 and j1, as texelWords gives them, when the lanes
// of `active` all read the row j0 of the first lane and a stretch of 2 x kLanes texels of it
// that begins at the first or the last lane's i0 and ends before the level's right edge (so i0 +
// 1 never wraps). Then the stretch is read whole from both rows and its texels moved to the
// lanes by table lookups instead of gathers (textured_scene 1 to 2% faster with AVX2 and
// AVX-512 on an AMD EPYC; gathers cost more on other processors). Returns false, writing
// nothing, otherwise, and always for vectors of fewer than 8 lanes (slower there).
template <class M, class VI, class VU>
HWY_INLINE bool texelWordsFromOneRow(const Sampler2D::Level& level, M activeLanes, VI i0, VI j0, VU (&words)[4]) {
  const hn::RebindToUnsigned<RowTag> du;
  const hn::RebindToSigned<RowTag> di;
  constexpr int kTable = static_cast<int>(hn::MaxLanes(du));
  if constexpr (kTable < 8) {
    return false;
  } else {
    // A row's texel coordinates run one way along it: its stretch begins at one of its ends.
    const int32_t iLow = std::min(hn::GetLane(i0), hn::ExtractLane(i0, kTable - 1));
    if (iLow + 2 * kTable > level.width) return false;
    const int32_t j = hn::GetLane(j0);
    const auto first = hn::Sub(i0, hn::Set(di, iLow));
    const auto inStretch = hn::And(hn::Eq(j0, hn::Set(di, j)),
                                   hn::And(hn::Gt(first, hn::Set(di, -1)), hn::Lt(first, hn::Set(di, 2 * kTable - 1))));
    if (!hn::AllTrue(di, hn::Or(inStretch, hn::Not(hn::RebindMask(di, activeLanes))))) return false;
    // Lanes outside `active` look anywhere in the stretch; their words are not used.
    const auto stretchEnd = hn::Set(di, 2 * kTable - 1);
    const auto left = hn::And(first, stretchEnd), right = hn::And(hn::Add(first, hn::Set(di, 1)), stretchEnd);
    auto fromStretch = [&](const uint8_t* stretch, auto at) {
      const auto low = hn::LoadU(du, reinterpret_cast<const uint32_t*>(stretch));
      const auto high = hn::LoadU(du, reinterpret_cast<const uint32_t*>(stretch) + kTable);
      const auto within = hn::IndicesFromVec(du, hn::And(at, hn::Set(di, kTable - 1)));
      const auto inLow = hn::RebindMask(du, hn::Lt(at, hn::Set(di, kTable)));
      return hn::IfThenElse(inLow, hn::TableLookupLanes(low, within), hn::TableLookupLanes(high, within));
    };
    const int jNext = (j + 1) & (level.height - 1);
    const uint8_t* row0 = level.texels + 4 * (static_cast<std::ptrdiff_t>(j) * level.width + iLow);
    const uint8_t* row1 = level.texels + 4 * (static_cast<std::ptrdiff_t>(jNext) * level.width + iLow);
    words[0] = fromStretch(row0, left);
    words[1] = fromStretch(row0, right);
    words[2] = fromStretch(row1, left);
    words[3] = fromStretch(row1, right);
    return true;
  }
}

// Sampler2D's LINEAR lookup in a power-of-two GL_REPEAT level, for the pixels `i .. i + lanes
// - 1` of the row whose bits are set in `lanes` and whose texel coordinates are below 2^20 in
// magnitude (the others would need keepInIntRange's reduction): writes out[c] for them and
// returns them.
inline unsigned bilinearRow(const Sampler2D::Level& level, const float* s, const float* t, unsigned lanes,
                            float out[4][kRowPixels]) {
  const RowTag f;
  const hn::RebindToSigned<RowTag> di;
  const int kLanes = static_cast<int>(hn::Lanes(f));
  const auto half = hn::Set(f, 0.5f), one = hn::Set(f, 1.0f), limit = hn::Set(f, 1048576.0f);
  const auto widthF = hn::Set(f, level.widthF), heightF = hn::Set(f, level.heightF);
  const auto widthMask = hn::Set(di, level.width - 1), heightMask = hn::Set(di, level.height - 1);
  const auto width = hn::Set(di, level.width);
  unsigned done = 0;
  for (int i = 0; i < kRowPixels; i += kLanes) {
    const auto uScaled = hn::Mul(hn::Load(f, s + i), widthF);
    const auto vScaled = hn::Mul(hn::Load(f, t + i), heightF);
    const uint8_t laneBits[8] = {static_cast<uint8_t>(lanes >> i)};
    const auto inRange = hn::And(hn::LoadMaskBits(f, laneBits),
                                 hn::And(hn::Lt(hn::Abs(uScaled), limit), hn::Lt(hn::Abs(vScaled), limit)));
    uint8_t inRangeBits[8] = {};
    hn::StoreMaskBits(f, inRange, inRangeBits);
    done |= static_cast<unsigned>(inRangeBits[0]) << i;
    // Other lanes compute with 0 instead, so that no conversion overflows and every texel read
    // is inside the image.
    const auto u = hn::Sub(hn::IfThenElseZero(inRange, uScaled), half);
    const auto v = hn::Sub(hn::IfThenElseZero(inRange, vScaled), half);
    // floorToInt: truncate, then one less where the truncation rounded up.
    auto floorOf = [&](auto x) {
      const auto truncated = hn::ConvertTo(di, x);
      const auto roundedUp = hn::RebindMask(di, hn::Gt(hn::ConvertTo(f, truncated), x));
      return hn::IfThenElse(roundedUp, hn::Sub(truncated, hn::Set(di, 1)), truncated);
    };
    const auto uWhole = floorOf(u), vWhole = floorOf(v);
    const auto alpha = hn::Sub(u, hn::ConvertTo(f, uWhole));
    const auto beta = hn::Sub(v, hn::ConvertTo(f, vWhole));
    const auto i0 = hn::And(uWhole, widthMask);
    const auto i1 = hn::And(hn::Add(i0, hn::Set(di, 1)), widthMask);
    const auto j0 = hn::And(vWhole, heightMask);
    const auto j1 = hn::And(hn::Add(j0, hn::Set(di, 1)), heightMask);
    decltype(hn::Zero(hn::RebindToUnsigned<RowTag>())) words[4];
    if (!texelWordsFromOneRow(level, inRange, i0, j0, words)) {
      const auto row0 = j0 * width, row1 = j1 * width;
      words[0] = texelWords(level.texels, hn::Add(row0, i0));
      words[1] = texelWords(level.texels, hn::Add(row0, i1));
      words[2] = texelWords(level.texels, hn::Add(row1, i0));
      words[3] = texelWords(level.texels, hn::Add(row1, i1));
    }
    const auto notAlpha = hn::Sub(one, alpha), notBeta = hn::Sub(one, beta);
    const decltype(hn::Zero(f)) weight[4] = {hn::Mul(notAlpha, notBeta), hn::Mul(alpha, notBeta),
                                             hn::Mul(notAlpha, beta), hn::Mul(alpha, beta)};
    hn::Store(bilinearComponent<0>(weight, words), f, out[0] + i);
    hn::Store(bilinearComponent<1>(weight, words), f, out[1] + i);
    hn::Store(bilinearComponent<2>(weight, words), f, out[2] + i);
    hn::Store(bilinearComponent<3>(weight, words), f, out[3] + i);
  }
  return done;
}

// The lookups of the pixels of `lanes`, which all read the levels of `choice` (a LINEAR one,
// both levels power-of-two GL_REPEAT): first level, then the second and the mix where
// choice.mixes and weight2[i] != 0 ... as Sampler2D::sampleChosen. Returns the pixels done.
inline unsigned sampleLevelPair(const Sampler2D& sampler, const Sampler2D::LevelChoice& choice,
                                const float* s, const float* t, const float* weight2, unsigned lanes,
                                unsigned mixedLanes, float texel[4][kRowPixels]) {
  unsigned done = bilinearRow(sampler.level(choice.level1), s, t, lanes, texel);
  const unsigned mixed = mixedLanes & done;
  if (mixed == 0) return done;
  alignas(64) float second[4][kRowPixels];
  const unsigned bothDone = bilinearRow(sampler.level(choice.level2), s, t, mixed, second);
  done &= ~(mixed & ~bothDone);  // a pixel whose second level fell outside takes Sampler2D
  const RowTag f;
  const int kLanes = static_cast<int>(hn::Lanes(f));
  for (int i = 0; i < kRowPixels; i += kLanes) {
    const uint8_t mixBits[8] = {static_cast<uint8_t>(bothDone >> i)};
    const auto mixesHere = hn::LoadMaskBits(f, mixBits);
    const auto w2 = hn::Load(f, weight2 + i);
    const auto w1 = hn::Sub(hn::Set(f, 1.0f), w2);
    for (int c = 0; c < 4; ++c) {
      const auto a = hn::Load(f, texel[c] + i), b = hn::Load(f, second[c] + i);
      // (1 - w2) first + w2 second, as Sampler2D::sampleChosen mixes the two levels.
      hn::Store(hn::IfThenElse(mixesHere, hn::Add(hn::Mul(w1, a), hn::Mul(w2, b)), a), f, texel[c] + i);
    }
  }
  return done;
}

// texel[c][i] = component c of sampler.sampleChosen(quadChoice[i / 2], s[i], t[i]) for each bit
// i of mask: pixels 2k and 2k + 1 form the row's part of 2x2 quad k, which reads the levels
// quadChoice[k] names (a lambda per quad). s and t hold kRowPixels entries each, quadChoice
// kRowQuads (those of pixels outside mask are not used).
constexpr int kRowQuads = kRowPixels / 2;
inline void sampleRow(const Sampler2D& sampler, const float* s, const float* t,
                      const Sampler2D::LevelChoice* quadChoice, unsigned mask, float texel[4][kRowPixels]) {
  // The quads of one level pair at a time (most rows read one pair).
  alignas(64) float weight2[kRowPixels] = {};
  unsigned done = 0;
  unsigned restQuads = 0;  // bit k: quad k has a pixel in mask not yet grouped
  for (int k = 0; k < kRowQuads; ++k)
    if ((mask >> (2 * k) & 3u) != 0) restQuads |= 1u << k;
  while (restQuads != 0) {
    const Sampler2D::LevelChoice& pair = quadChoice[std::countr_zero(restQuads)];
    unsigned lanes = 0, mixedLanes = 0, pairQuads = 0;
    for (unsigned r = restQuads; r != 0; r &= r - 1) {
      const int k = std::countr_zero(r);
      const Sampler2D::LevelChoice& quad = quadChoice[k];
      if (quad.level1 != pair.level1 || quad.level2 != pair.level2 || quad.linear != pair.linear) continue;
      pairQuads |= 1u << k;
      const unsigned pixels = (3u << (2 * k)) & mask;
      lanes |= pixels;
      if (quad.mixes) mixedLanes |= pixels;
      weight2[2 * k] = weight2[2 * k + 1] = quad.weight2;
    }
    restQuads &= ~pairQuads;
    const bool vectorRoute = pair.linear && sampler.level(pair.level1).repeatsByMask &&
                             sampler.level(pair.level2).repeatsByMask;
    if (!vectorRoute) continue;
    if (done == 0 && restQuads == 0) {  // one pair for the whole row (the usual case)
      done = sampleLevelPair(sampler, pair, s, t, weight2, lanes, mixedLanes, texel);
      break;
    }
    alignas(64) float pairTexel[4][kRowPixels];
    const unsigned pairDone = sampleLevelPair(sampler, pair, s, t, weight2, lanes, mixedLanes, pairTexel);
    for (unsigned r = pairDone; r != 0; r &= r - 1) {
      const int i = std::countr_zero(r);
      for (int c = 0; c < 4; ++c) texel[c][i] = pairTexel[c][i];
    }
    done |= pairDone;
  }
  for (unsigned r = mask & ~done; r != 0; r &= r - 1) {
    const int i = std::countr_zero(r);
    float one[4];
    sampler.sampleChosen(quadChoice[i / 2], s[i], t[i], one);
    for (int c = 0; c < 4; ++c) texel[c][i] = one[c];
  }
}

}  // namespace row_sampler
}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#endif  // GLASS_TEXTURE_ROW_SAMPLER_2D_INL_H_
