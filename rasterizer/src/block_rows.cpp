// coverBlockRows (block_rows.h), one template compiled for each SIMD target
// (hwy/foreach_target.h re-includes this file per target).
//
// What each lane computes, and why every target gives the same bits:
//   coverage   the three (four) edge values at the pixel centre, as 64-bit integers: the row's start
//              plus the column's step (both exact), OR-ed; the centre is inside when the sign
//              bit is clear (edge_functions.h: "E + bias - 1 >= 0" for all three).
//   depth      depthValue(column + row) of depth_value.h: one double addition, the clamps to
//              [0, 1] as comparisons and selections (NaN compares false and becomes 0), one
//              multiplication, one addition and the truncation to a 32-bit integer.
//   early test the fragment's depth against the stored one, as 32-bit signed integers (depths
//              are below 2^24, so signed order is unsigned order).
// A row's depths are computed for all eight columns (the uncovered ones are never read). The
// stored depths are read for all eight columns only inside the thread's own tile (storedWhole);
// elsewhere for the box's columns only, since the columns beyond may belong to another tile,
// which another thread may be drawing.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "block_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>
#include <cstring>

#include "block_rows.h"
#include "depth_value-inl.h"
#include "glass/raster/simd_target.h"

HWY_BEFORE_NAMESPACE();
namespace glass::raster {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

constexpr int kSize = BlockRows::kSize;

// Bit i: column i's centre of the current row is inside the kEdges edges.
template <int kEdges>
HWY_INLINE unsigned rowCoverage(const BlockRows& rows, const int64_t rowStart[kEdges]) {
  const hn::CappedTag<int64_t, kSize> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  unsigned outside = 0;
  for (int i = 0; i < kSize; i += lanes) {
    auto any = hn::Zero(d);
    for (int k = 0; k < kEdges; ++k)
      any = hn::Or(any, hn::Add(hn::Set(d, rowStart[k]), hn::LoadU(d, rows.columnStep[k] + i)));
    uint8_t bits[8] = {};
    hn::StoreMaskBits(d, hn::Lt(any, hn::Zero(d)), bits);
    outside |= static_cast<unsigned>(bits[0]) << i;
  }
  return ~outside & 0xFFu;
}

// Row j's depths, all eight columns, into z.
HWY_INLINE void rowDepths(const BlockRows& rows, int j, uint32_t z[kSize]) {
  const hn::CappedTag<double, kSize> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto row = hn::Set(d, rows.depthRow[j]);
  auto* out = reinterpret_cast<int32_t*>(z);  // depths are below 2^24: the same bits either way
  for (int i = 0; i < kSize; i += lanes) storeDepthValues(d, hn::Add(hn::LoadU(d, rows.depthColumn + i), row), out + i);
}

// Which orderings of a fragment's depth against the stored one pass rows.compare, each as the
// mask of a whole row (all ones or none), from passesDepthCompare itself.
struct PassingOrders {
  unsigned less, equal, greater;
  explicit PassingOrders(DepthCompare compare)
      : less(passesDepthCompare(compare, 0, 1) ? 0xFFu : 0u),
        equal(passesDepthCompare(compare, 1, 1) ? 0xFFu : 0u),
        greater(passesDepthCompare(compare, 1, 0) ? 0xFFu : 0u) {}
};

// Bit i: column i's depth z[i] passes the early test against the stored row (columns in
// rows.columns only; the others give 0).
HWY_INLINE unsigned rowDepthPasses(const BlockRows& rows, const PassingOrders& passing, int j,
                                   const uint32_t z[kSize]) {
  const hn::CappedTag<int32_t, kSize> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const uint32_t* stored = rows.stored + j * rows.storedStride;
  int32_t storedRow[kSize] = {};
  if (rows.storedWhole) {
    std::memcpy(storedRow, stored, sizeof storedRow);
  } else {
    for (int i = std::countr_zero(rows.columns), end = static_cast<int>(std::bit_width(rows.columns)); i < end; ++i)
      storedRow[i] = static_cast<int32_t>(stored[i]);
  }
  const auto* fragments = reinterpret_cast<const int32_t*>(z);
  unsigned less = 0, equal = 0;
  for (int i = 0; i < kSize; i += lanes) {
    const auto fragment = hn::LoadU(d, fragments + i), held = hn::LoadU(d, storedRow + i);
    uint8_t bits[8] = {};
    hn::StoreMaskBits(d, hn::Lt(fragment, held), bits);
    less |= static_cast<unsigned>(bits[0]) << i;
    hn::StoreMaskBits(d, hn::Eq(fragment, held), bits);
    equal |= static_cast<unsigned>(bits[0]) << i;
  }
  const unsigned greater = ~(less | equal);
  return ((less & passing.less) | (equal & passing.equal) | (greater & passing.greater)) & rows.columns;
}

template <int kEdges>
bool coverRows(const BlockRows& rows, CoveredBlock& block) {
  std::memset(block.rowMask, 0, sizeof block.rowMask);
  int64_t rowStart[kEdges];
  for (int k = 0; k < kEdges; ++k) rowStart[k] = rows.rowStart[k];
  const PassingOrders passing(rows.compare);
  bool any = false;
  for (int j = rows.firstRow; j < rows.endRow; ++j) {
    unsigned mask = rows.columns;
    if (!rows.accepted) {
      mask &= rowCoverage<kEdges>(rows, rowStart);
      for (int k = 0; k < kEdges; ++k) rowStart[k] += rows.stepY[k];
    }
    if (mask == 0) continue;
    if (rows.depthColumn != nullptr) {
      rowDepths(rows, j, block.depth[j]);
    } else {
      std::memset(block.depth[j], 0, sizeof block.depth[j]);
    }
    if (rows.stored != nullptr) mask &= rowDepthPasses(rows, passing, j, block.depth[j]);
    block.rowMask[j] = static_cast<uint8_t>(mask);
    any |= mask != 0;
  }
  return any;
}

}  // namespace

bool CoverBlockRows(const BlockRows& rows, CoveredBlock& block) {
  return rows.edgeCount == 4 ? coverRows<4>(rows, block) : coverRows<3>(rows, block);
}

void BlockDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, uint32_t& lowest,
                     uint32_t& highest) {
  // As signed integers: stored depths are below 2^24.
  const hn::CappedTag<int32_t, kSize> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  auto low = hn::Set(d, static_cast<int32_t>(kDepthMax)), high = hn::Zero(d);
  for (int r = 0; r < rowCount; ++r) {
    const auto* row = reinterpret_cast<const int32_t*>(stored + r * stride);
    for (int i = 0; i < kSize; i += lanes) {
      const auto values = hn::LoadU(d, row + i);
      low = hn::Min(low, values);
      high = hn::Max(high, values);
    }
  }
  lowest = static_cast<uint32_t>(hn::GetLane(hn::MinOfLanes(d, low)));
  highest = static_cast<uint32_t>(hn::GetLane(hn::MaxOfLanes(d, high)));
}

void BlockColumnsDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, unsigned columns,
                            uint32_t& lowest, uint32_t& highest) {
  // All eight columns are read; those outside `columns` are left out by selection.
  const hn::CappedTag<int32_t, kSize> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto none = hn::Set(d, static_cast<int32_t>(kDepthMax));
  auto low = none, high = hn::Zero(d);
  for (int i = 0; i < kSize; i += lanes) {
    const uint8_t columnBits[8] = {static_cast<uint8_t>(columns >> i)};
    const auto inside = hn::LoadMaskBits(d, columnBits);
    for (int r = 0; r < rowCount; ++r) {
      const auto values = hn::LoadU(d, reinterpret_cast<const int32_t*>(stored + r * stride) + i);
      low = hn::Min(low, hn::IfThenElse(inside, values, none));
      high = hn::Max(high, hn::IfThenElseZero(inside, values));
    }
  }
  lowest = static_cast<uint32_t>(hn::GetLane(hn::MinOfLanes(d, low)));
  highest = static_cast<uint32_t>(hn::GetLane(hn::MaxOfLanes(d, high)));
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::raster {
namespace {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(CoverBlockRows))> kCoverBlockRows =
    GLASS_SIMD_FUNCTIONS(CoverBlockRows);
constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(BlockDepthRange))> kBlockDepthRange =
    GLASS_SIMD_FUNCTIONS(BlockDepthRange);
constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(BlockColumnsDepthRange))> kBlockColumnsDepthRange =
    GLASS_SIMD_FUNCTIONS(BlockColumnsDepthRange);

}  // namespace

bool coverBlockRows(const BlockRows& rows, CoveredBlock& block) {
  return chosenSimdFunction(kCoverBlockRows)(rows, block);
}

void blockDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, uint32_t& lowest,
                     uint32_t& highest) {
  chosenSimdFunction(kBlockDepthRange)(stored, stride, rowCount, lowest, highest);
}

void blockColumnsDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, unsigned columns,
                            uint32_t& lowest, uint32_t& highest) {
  chosenSimdFunction(kBlockColumnsDepthRange)(stored, stride, rowCount, columns, lowest, highest);
}

bool coverBlockRowsWith(SimdTarget target, const BlockRows& rows, CoveredBlock& block) {
  return kCoverBlockRows[static_cast<int>(target)](rows, block);
}

void blockDepthRangeWith(SimdTarget target, const uint32_t* stored, ptrdiff_t stride, int rowCount,
                         uint32_t& lowest, uint32_t& highest) {
  kBlockDepthRange[static_cast<int>(target)](stored, stride, rowCount, lowest, highest);
}

void blockColumnsDepthRangeWith(SimdTarget target, const uint32_t* stored, ptrdiff_t stride, int rowCount,
                                unsigned columns, uint32_t& lowest, uint32_t& highest) {
  kBlockColumnsDepthRange[static_cast<int>(target)](stored, stride, rowCount, columns, lowest, highest);
}

}  // namespace glass::raster
#endif
