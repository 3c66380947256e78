// Texture lookups for a row of up to eight pixels at once, the row of a fragment kernel's block
// (fragment/block_kernels.h): texel[c][i] is component c of what Sampler2D::sample (or
// sampleMagnified) gives for pixel i, bit for bit.
//
// The common case of textured drawing -- LINEAR filtering within power-of-two GL_REPEAT levels,
// one level or two mixed (GL_LINEAR_MIPMAP_LINEAR) -- runs on vectors of pixels: one 32-bit lane
// per pixel for the coordinates (the same IEEE operations as Sampler2D's sampleLinear), then the
// fixed-point filter of texel_filter.h in 16-bit lanes, two components of a pixel in each 32-bit
// lane (red and blue, green and alpha: a texel's bytes masked 0x00FF00FF), so that one
// multiplication serves two components. Integer arithmetic gives the scalar result's bits on
// every SIMD target. The pixels of a row may read different levels (a lambda per 2x2 quad): they
// are taken one level pair at a time.
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

// Operations on both 16-bit halves of each 32-bit lane: the lanes seen as twice as many 16-bit
// lanes, or, for one-lane vectors (which have no such view), the two halves worked apart.
#if HWY_TARGET == HWY_SCALAR
template <class VU, class Op>
HWY_INLINE VU eachHalf(VU a, VU b, Op op) {
  const uint32_t x = hn::GetLane(a), y = hn::GetLane(b);
  const uint32_t low = op(x & 0xFFFFu, y & 0xFFFFu) & 0xFFFFu, high = op(x >> 16, y >> 16) & 0xFFFFu;
  return hn::Set(hn::DFromV<VU>(), low | high << 16);
}
template <class VU>
HWY_INLINE VU halvesMul(VU a, VU b) { return eachHalf(a, b, [](uint32_t x, uint32_t y) { return x * y; }); }
template <class VU>
HWY_INLINE VU halvesMulHigh(VU a, VU b) { return eachHalf(a, b, [](uint32_t x, uint32_t y) { return x * y >> 16; }); }
template <class VU>
HWY_INLINE VU halvesAdd(VU a, VU b) { return eachHalf(a, b, [](uint32_t x, uint32_t y) { return x + y; }); }
template <class VU>
HWY_INLINE VU halvesSub(VU a, VU b) { return eachHalf(a, b, [](uint32_t x, uint32_t y) { return x - y; }); }
#else
template <class VU, class Op>
HWY_INLINE VU asHalves(VU a, VU b, Op op) {
  const hn::Repartition<uint16_t, hn::DFromV<VU>> d16;
  return hn::BitCast(hn::DFromV<VU>(), op(hn::BitCast(d16, a), hn::BitCast(d16, b)));
}
template <class VU>
HWY_INLINE VU halvesMul(VU a, VU b) { return asHalves(a, b, [](auto x, auto y) { return hn::Mul(x, y); }); }
template <class VU>
HWY_INLINE VU halvesMulHigh(VU a, VU b) { return asHalves(a, b, [](auto x, auto y) { return hn::MulHigh(x, y); }); }
template <class VU>
HWY_INLINE VU halvesAdd(VU a, VU b) { return asHalves(a, b, [](auto x, auto y) { return hn::Add(x, y); }); }
template <class VU>
HWY_INLINE VU halvesSub(VU a, VU b) { return asHalves(a, b, [](auto x, auto y) { return hn::Sub(x, y); }); }
#endif

// texel_filter::mixFixed on the halves, whose weights w are in `weights`' halves:
// x0 + floor(x1 w / 65536) - floor(x0 w / 65536), each product's high half.
template <class VU>
HWY_INLINE VU mixHalves(VU x0, VU x1, VU weights) {
  return halvesSub(halvesAdd(x0, halvesMulHigh(x1, weights)), halvesMulHigh(x0, weights));
}

// texel_filter::mixTexels on the halves: t0 (256 - a) + t1 a, with a (and 256 - a) in both
// halves of each lane.
template <class VU>
HWY_INLINE VU mixTexelHalves(VU t0, VU t1, VU a, VU notA) {
  return halvesAdd(halvesMul(t0, notA), halvesMul(t1, a));
}

// A per-lane value v (below 2^16) in both 16-bit halves of its lane.
template <class VU>
HWY_INLINE VU inBothHalves(VU v) {
  return hn::Or(v, hn::ShiftLeft<16>(v));
}

// Where a texel word's components land in filterLevel's results (bytes in memory order R, G, B,
// A): the word masked 0x00FF00FF (`masked`) holds the components of bytes 0 and 2, the word
// shifted right by 8 and masked (`shifted`) those of bytes 1 and 3; component c is in the low
// half of one of them or the high.
constexpr bool kLittleEndian = std::endian::native == std::endian::little;
constexpr bool inMaskedWord(int c) { return (kLittleEndian ? c : 3 - c) % 2 == 0; }
constexpr bool inHighHalf(int c) { return (kLittleEndian ? c : 3 - c) >= 2; }

// A level's LINEAR lookups for one vector of the row's pixels: the coordinates scaled to the
// level, s * width and t * height, and the lanes to look up (their coordinates below 2^20 in
// magnitude; the others compute with 0 instead, so that no conversion overflows and every texel
// read is inside the image). Writes the filtered texels, two components per lane in each of
// `masked` (the components of the texel word masked 0x00FF00FF) and `shifted` (of the word
// shifted right by 8): Sampler2D's sampleLinear in a power-of-two GL_REPEAT level.
template <class VF, class M, class VU>
HWY_INLINE void filterLevel(const Sampler2D::Level& level, VF uScaled, VF vScaled, M active, VU& masked,
                            VU& shifted) {
  const RowTag f;
  const hn::RebindToSigned<RowTag> di;
  const hn::RebindToUnsigned<RowTag> du;
  const auto half = hn::Set(f, 0.5f);
  // texel_filter::fixedCoordinate, then floorToInt: truncate, then one less where the
  // truncation rounded up.
  auto fixedCoordinate = [&](VF scaled) {
    const auto x = hn::Add(hn::Mul(hn::Sub(hn::IfThenElseZero(active, scaled), half), hn::Set(f, 256.0f)), half);
    const auto truncated = hn::ConvertTo(di, x);
    const auto roundedUp = hn::RebindMask(di, hn::Gt(hn::ConvertTo(f, truncated), x));
    return hn::IfThenElse(roundedUp, hn::Sub(truncated, hn::Set(di, 1)), truncated);
  };
  const auto u = fixedCoordinate(uScaled), v = fixedCoordinate(vScaled);
  const auto widthMask = hn::Set(di, level.width - 1), heightMask = hn::Set(di, level.height - 1);
  const auto i0 = hn::And(hn::ShiftRight<8>(u), widthMask);
  const auto i1 = hn::And(hn::Add(i0, hn::Set(di, 1)), widthMask);
  const auto j0 = hn::And(hn::ShiftRight<8>(v), heightMask);
  const auto j1 = hn::And(hn::Add(j0, hn::Set(di, 1)), heightMask);
  VU words[4];
  if (!texelWordsFromOneRow(level, active, i0, j0, words)) {
    const auto width = hn::Set(di, level.width);
    const auto row0 = hn::Mul(j0, width), row1 = hn::Mul(j1, width);
    words[0] = texelWords(level.texels, hn::Add(row0, i0));
    words[1] = texelWords(level.texels, hn::Add(row0, i1));
    words[2] = texelWords(level.texels, hn::Add(row1, i0));
    words[3] = texelWords(level.texels, hn::Add(row1, i1));
  }
  const auto weightMask = hn::Set(di, 255);
  const auto a = inBothHalves(hn::BitCast(du, hn::And(u, weightMask)));
  const auto notA = hn::Sub(hn::Set(du, 0x01000100u), a);
  const auto rowWeight = hn::ShiftLeft<8>(inBothHalves(hn::BitCast(du, hn::And(v, weightMask))));
  auto filter = [&](auto component) {  // component(word): two components in the halves
    return mixHalves(mixTexelHalves(component(words[0]), component(words[1]), a, notA),
                     mixTexelHalves(component(words[2]), component(words[3]), a, notA), rowWeight);
  };
  const auto byteMask = hn::Set(du, 0x00FF00FFu);
  masked = filter([&](VU w) { return hn::And(w, byteMask); });
  shifted = filter([&](VU w) { return hn::And(hn::ShiftRight<8>(w), byteMask); });
}

// The lookups of the pixels of `lanes`, which all read the levels of `choice` (a LINEAR one,
// both levels power-of-two GL_REPEAT), as Sampler2D::sampleChosen: the first level, then for
// the pixels of mixedLanes the second and the mix by weight2[i]. Both levels are looked up in
// one pass over the row's vectors. Returns the pixels done: those whose coordinates are below
// 2^20 texels in magnitude (in both levels where they mix); the others take Sampler2D.
inline unsigned sampleLevelPair(const Sampler2D& sampler, const Sampler2D::LevelChoice& choice,
                                const float* s, const float* t, const uint32_t* weight2, unsigned lanes,
                                unsigned mixedLanes, float texel[4][kRowPixels]) {
  const RowTag f;
  const hn::RebindToSigned<RowTag> di;
  const hn::RebindToUnsigned<RowTag> du;
  const int kLanes = static_cast<int>(hn::Lanes(f));
  const Sampler2D::Level& first = sampler.level(choice.level1);
  const Sampler2D::Level& second = sampler.level(choice.level2);
  const auto limit = hn::Set(f, 1048576.0f);
  auto inRange = [&](auto uScaled, auto vScaled) {
    return hn::And(hn::Lt(hn::Abs(uScaled), limit), hn::Lt(hn::Abs(vScaled), limit));
  };
  auto laneMask = [&](unsigned bits, int i) {
    const uint8_t laneBits[8] = {static_cast<uint8_t>(bits >> i)};
    return hn::LoadMaskBits(f, laneBits);
  };
  auto maskBits = [&](auto mask, int i) {
    uint8_t bits[8] = {};
    hn::StoreMaskBits(f, mask, bits);
    return static_cast<unsigned>(bits[0]) << i;
  };
  const auto scale = hn::Set(f, 1.0f / 65280.0f);
  const auto lowHalf = hn::Set(du, 0xFFFFu);
  unsigned done = 0;
  for (int i = 0; i < kRowPixels; i += kLanes) {
    const auto sv = hn::Load(f, s + i), tv = hn::Load(f, t + i);
    const auto uScaled = hn::Mul(sv, hn::Set(f, first.widthF)), vScaled = hn::Mul(tv, hn::Set(f, first.heightF));
    const auto active = hn::And(laneMask(lanes, i), inRange(uScaled, vScaled));
    decltype(hn::Zero(du)) masked, shifted;
    filterLevel(first, uScaled, vScaled, active, masked, shifted);
    done |= maskBits(active, i);
    const auto mixing = hn::And(active, laneMask(mixedLanes, i));
    if (!hn::AllFalse(f, mixing)) {
      const auto uScaled2 = hn::Mul(sv, hn::Set(f, second.widthF));
      const auto vScaled2 = hn::Mul(tv, hn::Set(f, second.heightF));
      const auto mixes = hn::And(mixing, inRange(uScaled2, vScaled2));
      done &= ~(maskBits(mixing, i) & ~maskBits(mixes, i));  // outside in the second level: Sampler2D
      decltype(hn::Zero(du)) masked2, shifted2;
      filterLevel(second, uScaled2, vScaled2, mixes, masked2, shifted2);
      const auto w = inBothHalves(hn::Load(du, weight2 + i));
      const auto mixesHere = hn::RebindMask(du, mixes);
      masked = hn::IfThenElse(mixesHere, mixHalves(masked, masked2, w), masked);
      shifted = hn::IfThenElse(mixesHere, mixHalves(shifted, shifted2, w), shifted);
    }
    for (int c = 0; c < 4; ++c) {
      const auto pair = inMaskedWord(c) ? masked : shifted;
      const auto fixed = inHighHalf(c) ? hn::ShiftRight<16>(pair) : hn::And(pair, lowHalf);
      // texel_filter::unitFromFixed (the value is below 2^16: converted as signed).
      hn::Store(hn::Mul(hn::ConvertTo(f, hn::BitCast(di, fixed)), scale), f, texel[c] + i);
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
  alignas(64) uint32_t weight2[kRowPixels] = {};
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
      weight2[2 * k] = weight2[2 * k + 1] = static_cast<uint32_t>(quad.weight2);
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
