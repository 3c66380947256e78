// testStencilAndDepth (fragment/stencil_depth_tests.h) on the pixels of a block row at once, for
// the block kernels of stencil-tested draws: a pixel per 32-bit lane, each lane doing the same
// comparisons and stencil operations on the same values (the stencil bytes widened to 32 bits,
// the depths unsigned), so that every pixel ends with the stencil and depth values, and the
// outcome, that the function gives it. The pixels are independent of each other (a row holds
// each pixel once), so testing them together gives what testing them one after another gives.
//
// Only the pixels of the row's mask are read and written: the others may be another thread's
// (in the next tile) or lie past the row's end.
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each). The unit test stencil_depth_rows compares it with testStencilAndDepth on every target.
#if defined(GLASS_FRAGMENT_STENCIL_DEPTH_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_FRAGMENT_STENCIL_DEPTH_ROWS_INL_H_
#undef GLASS_FRAGMENT_STENCIL_DEPTH_ROWS_INL_H_
#else
#define GLASS_FRAGMENT_STENCIL_DEPTH_ROWS_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

#include "fragment/covered_pixels.h"
#include "fragment/stencil_depth_tests.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace stencil_depth_rows {

namespace hn = hwy::HWY_NAMESPACE;

constexpr int kRowPixels = 8;
using RowWords = hn::CappedTag<uint32_t, kRowPixels>;
using Word = hn::Vec<RowWords>;
using WordMask = hn::Mask<RowWords>;

// passesComparison(func, incoming, stored) in each lane (unsigned values).
inline WordMask passes(RowWords d, GLenum func, Word incoming, Word stored) {
  switch (func) {
    case GL_NEVER: return hn::FirstN(d, 0);
    case GL_LESS: return hn::Lt(incoming, stored);
    case GL_EQUAL: return hn::Eq(incoming, stored);
    case GL_LEQUAL: return hn::Not(hn::Gt(incoming, stored));
    case GL_GREATER: return hn::Gt(incoming, stored);
    case GL_NOTEQUAL: return hn::Not(hn::Eq(incoming, stored));
    case GL_GEQUAL: return hn::Not(hn::Lt(incoming, stored));
    default: return hn::FirstN(d, hn::Lanes(d));  // GL_ALWAYS
  }
}

// applyStencilOperation(op, value, reference) in each lane (values 0 to 255).
inline Word stencilOperation(RowWords d, GLenum op, Word value, Word reference) {
  const Word one = hn::Set(d, 1u), full = hn::Set(d, 255u);
  switch (op) {
    case GL_ZERO: return hn::Zero(d);
    case GL_REPLACE: return reference;
    case GL_INCR: return hn::Min(hn::Add(value, one), full);  // stays at 255
    case GL_DECR: return hn::Sub(hn::Max(value, one), one);   // stays at 0
    case GL_INVERT: return hn::Xor(value, full);
    case GL_INCR_WRAP: return hn::And(hn::Add(value, one), full);
    case GL_DECR_WRAP: return hn::And(hn::Sub(value, one), full);
    default: return value;  // GL_KEEP
  }
}

// testStencilAndDepth(s, &stencil[i], &depth[i], fragmentDepth[i]) for each bit i of mask (of
// kRowPixels), in any order; stencil is used only when s.stencilTest is on, depth only when
// s.depthTest is. Returns the pixels of mask that passed both tests. A whole row is read and
// written in place; the pixels of a part of a row are copied out first and back after.
inline unsigned testStencilAndDepthRow(const StencilDepthSettings& s, uint8_t* stencil, uint32_t* depth,
                                       const uint32_t* fragmentDepth, unsigned mask) {
  const RowWords d;
  const hn::Rebind<uint8_t, RowWords> bytes;
  const hn::RebindToSigned<RowWords> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const bool wholeRow = mask == (1u << kRowPixels) - 1u;
  alignas(64) uint8_t coveredStencil[kRowPixels] = {};
  alignas(64) uint32_t coveredDepth[kRowPixels] = {};
  uint8_t* stencilRow = stencil;
  uint32_t* depthRow = depth;
  if (!wholeRow) {
    if (s.stencilTest) copyCoveredPixels<1>(coveredStencil, stencil, mask);
    if (s.depthTest) copyCoveredWords(coveredDepth, depth, mask);
    stencilRow = coveredStencil;
    depthRow = coveredDepth;
  }
  const Word valueMask = hn::Set(d, s.stencilValueMask), writeMask = hn::Set(d, s.stencilWriteMask & 0xFFu);
  const Word reference = hn::Set(d, s.stencilRef);
  const Word maskedReference = hn::And(reference, valueMask);
  unsigned passed = 0;
  for (int i = 0; i < kRowPixels; i += lanes) {
    // Pixels that fail the stencil test stop there: they get the stencil-fail operation. A test
    // that is off passes, as GL_ALWAYS does.
    const Word value = s.stencilTest ? hn::PromoteTo(d, hn::LoadU(bytes, stencilRow + i)) : hn::Zero(d);
    const WordMask stencilPasses =
        passes(d, s.stencilTest ? s.stencilFunc : GL_ALWAYS, maskedReference, hn::And(value, valueMask));
    const Word fragment = hn::LoadU(d, fragmentDepth + i);
    const Word stored = s.depthTest ? hn::LoadU(d, depthRow + i) : hn::Zero(d);
    const WordMask depthPasses = passes(d, s.depthTest ? s.depthFunc : GL_ALWAYS, fragment, stored);
    const WordMask both = hn::And(stencilPasses, depthPasses);
    if (s.stencilTest) {
      const Word updated = hn::IfThenElse(
          stencilPasses,
          hn::IfThenElse(depthPasses, stencilOperation(d, s.stencilDepthPass, value, reference),
                         stencilOperation(d, s.stencilDepthFail, value, reference)),
          stencilOperation(d, s.stencilFail, value, reference));
      const Word written = hn::Or(hn::AndNot(writeMask, value), hn::And(updated, writeMask));
      hn::StoreU(hn::DemoteTo(bytes, hn::BitCast(di, written)), bytes, stencilRow + i);  // 0 to 255
    }
    if (s.depthTest && s.depthMask) hn::StoreU(hn::IfThenElse(both, fragment, stored), d, depthRow + i);
    uint8_t bits[8] = {};
    hn::StoreMaskBits(d, both, bits);
    passed |= static_cast<unsigned>(bits[0]) << i;
  }
  if (!wholeRow) {
    if (s.stencilTest) copyCoveredPixels<1>(stencil, coveredStencil, mask);
    if (s.depthTest && s.depthMask) copyCoveredWords(depth, coveredDepth, mask & passed);
  }
  return mask & passed;
}

}  // namespace stencil_depth_rows
}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
