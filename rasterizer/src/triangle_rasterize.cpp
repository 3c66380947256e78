// Triangle coverage: walks the setup's bounding box in 8x8 blocks, and hands each block's
// fragments to the sink in one batch. The blocks start at the box's lower-left corner, its column
// rounded down to an even one (the 2x2 quads of texture level of detail pair columns 2k and
// 2k + 1, so no quad straddles two blocks). Every value of a pixel comes from its own position,
// never from its block's (see "Attributes" below), so a pixel gets the same fragment whichever
// block holds it: the whole window, a 64 x 64 tile of the tiled rasterizer or a scissor may start
// the blocks anywhere. Starting at the box rather than on a fixed grid puts most small triangles
// in one block, where a grid of multiples of 8 cuts most of them into two to four.
//
// Fill rule. A pixel is covered when its centre is strictly inside all three edges (all four of
// a convex quadrilateral, setupQuad), or exactly on an edge that owns its centres. Of two
// triangles sharing an edge exactly one owns it: the edge
// owns its centres when it is a left edge (the interior lies to its right: A > 0) or a bottom edge
// (horizontal with the interior above it: A == 0, B > 0), in GL window coordinates where y points
// up. This is the "top-left" rule of raster systems whose rows run downwards, seen from GL's
// bottom-up window coordinates; it is the convention Mesa's llvmpipe applies to GL framebuffers, so
// glass and the reference renderer agree on edge pixels. In integers, "E > 0, or E == 0 on an
// owning edge" is "E + bias - 1 >= 0" with bias = 1 on owning edges, and a pixel is inside when the
// three biased values are all non-negative: (e0 | e1 | e2) >= 0.
//
// Blocks. Each edge function is affine, so over a block its extreme values lie at corners. A block
// whose best corner is outside some edge is rejected whole; a block whose worst corner is inside
// every edge is accepted whole, with no per-pixel test; only blocks the edges cross are tested
// pixel by pixel.
//
// Attributes are evaluated directly at each pixel centre from the setup's planes (never by
// accumulating increments), so a pixel's values do not depend on the order blocks are visited.
// Evaluating v0 + dvdx x + dvdy y at a centre computes (v0 + dvdx x) + dvdy y: the sum depends
// only on the column and the product only on the row, so a block computes those once per column
// and row and adds them per pixel. Those are the same operations in the same order, so the values
// have the same bits as when each pixel is evaluated on its own.
//
// Depth comes first, so that the early depth test (depth_test.h) can drop hidden fragments
// before their varyings are interpolated: with many overlapping triangles most fragments are
// hidden, and the divisions of perspective-correct interpolation are the costliest part. When
// nothing reads depth (the depth test is off: TriangleSettings::depthUsed), the walk leaves out
// the block's depth plane and the rows' depths, and the fragments carry depth 0.
//
// Hidden blocks. The depth a pixel gets, depthValue(column + row) with column and row as above,
// never decreases (or never increases) from one column to the next, nor from one row to the
// next: each step is one IEEE operation rounded to nearest, and rounding keeps the order of its
// arguments. So over a rectangle of pixels its extremes are at the four corners, exactly. When
// the early depth test is an ordering (LESS, LEQUAL, GREATER, GEQUAL) and the nearest corner
// fails against the farthest value stored in the rectangle, every pixel of the block fails and
// the block is dropped before any per-pixel work; when the farthest corner passes against the
// nearest stored value, every pixel passes and none is compared. A large triangle's blocks (and
// any block wholly inside a triangle) are looked at so; a small triangle's block has too few
// pixels to repay the look, so it is only tested for being hidden, from the one corner the
// plane's slopes make the nearest, against its whole rows of stored depths in vector lanes, and
// only where such tests have found hidden blocks lately (hidden_block_odds.h): many small
// triangles behind others (lit_spheres) lose 4% of their instructions, and small triangles that
// are seldom hidden (small_triangles, 3% of the blocks) pay under 1% for the tests.
//
// Rows. Each row of a block is worked as vector lanes without branches (block_rows.h): the
// coverage of its eight centres as a bit mask, the depths of all its columns, and the early depth
// test, in SIMD code compiled for every target (glass/raster/simd_target.h), each lane the same
// integer or IEEE operations as evaluating one pixel alone. Loops over the covered pixels alone
// were slower: their branches follow the triangle's shape and are mispredicted.
//
// The walk ends at a CoveredBlock (triangle_block.h): which pixels of the block are covered and
// passed the early test, and their depths. The sink decides what happens next; by default it is
// the reference path below (emitBlockFragments), which interpolates every varying.
#include <algorithm>

#include "block_rows.h"
#include "glass/raster/depth_value.h"
#include "edge_functions.h"
#include "hidden_block_odds.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/triangle.h"
#include "glass/raster/triangle_block.h"

namespace glass::raster {
namespace {

constexpr int kBlockSize = CoveredBlock::kSize;

// The depth plane at the block's pixel centres, split as described at the top of the file.
// Made with the corner columns and rows of the box's part of the block only (i0 and i1 - 1, j0
// and j1 - 1: all the hidden-block test reads); fillInterior() sets all eight columns and the rows
// [j0, j1) for the block rows, which compute a row's depths whole, whichever of its pixels are
// covered (the others are never read). Every entry is the same expression either way.
struct BlockDepth {
  const TriangleSetup& setup;
  int bx, by, j0, j1;
  double column[kBlockSize], row[kBlockSize];

  BlockDepth(const TriangleSetup& s, int x, int y, int firstColumn, int endColumn, int firstRow, int endRow)
      : setup(s), bx(x), by(y), j0(firstRow), j1(endRow) {
    setColumn(firstColumn);
    setColumn(endColumn - 1);
    setRow(j0);
    setRow(j1 - 1);
  }
  void fillInterior() {
    for (int i = 0; i < kBlockSize; ++i) setColumn(i);
    for (int j = j0 + 1; j < j1 - 1; ++j) setRow(j);
  }
  uint32_t at(int i, int j) const { return depthValue(column[i] + row[j]); }

 private:
  void setColumn(int i) { column[i] = setup.z0 + setup.zdx * (bx + i + 0.5); }
  void setRow(int j) { row[j] = setup.zdy * (by + j + 0.5); }
};

// Bits i0 <= i < i1.
unsigned columnMask(int i0, int i1) { return (0xFFu << i0) & (0xFFu >> (kBlockSize - i1)); }

// The smallest and largest stored depth over columns [x0, x1) of rows [y0, y1): whole block rows
// in vector lanes (block_rows.h), others pixel by pixel.
[[gnu::always_inline]] inline void storedDepthRange(const Framebuffer& fb, int x0, int x1, int y0, int y1,
                                                   uint32_t& lowest, uint32_t& highest) {
  lowest = kDepthMax;
  highest = 0;
  if (x1 - x0 == kBlockSize) return blockDepthRange(fb.depthAt(x0, y0), fb.width(), y1 - y0, lowest, highest);
  for (int y = y0; y < y1; ++y) {
    const uint32_t* stored = fb.depthAt(0, y);
    for (int x = x0; x < x1; ++x) {
      lowest = std::min(lowest, stored[x]);
      highest = std::max(highest, stored[x]);
    }
  }
}

// The orderings among the early depth comparisons, for which a block's depth range can decide:
// nearer fragments pass (LESS, LEQUAL) or farther ones (GREATER, GEQUAL).
constexpr bool nearerPasses(DepthCompare c) { return c == DepthCompare::Less || c == DepthCompare::LessEqual; }
constexpr bool fartherPasses(DepthCompare c) {
  return c == DepthCompare::Greater || c == DepthCompare::GreaterEqual;
}

// What the early depth test decides for a whole block from its depth range and the stored
// range (see "Hidden blocks" above).
enum class BlockDepthOutcome { AllFail, AllPass, PerPixel };

template <DepthCompare kCompare>
[[gnu::always_inline]] inline BlockDepthOutcome blockDepthOutcome(const BlockDepth& depth, const Framebuffer& fb,
                                                                  int bx, int by, int x0, int x1, int y0, int y1) {
  constexpr bool kNearerPasses = nearerPasses(kCompare), kFartherPasses = fartherPasses(kCompare);
  if constexpr (!kNearerPasses && !kFartherPasses) {
    return BlockDepthOutcome::PerPixel;
  } else {
    const int i0 = x0 - bx, i1 = x1 - 1 - bx, j0 = y0 - by, j1 = y1 - 1 - by;
    const uint32_t corners[4] = {depth.at(i0, j0), depth.at(i1, j0), depth.at(i0, j1), depth.at(i1, j1)};
    const uint32_t zMin = *std::min_element(corners, corners + 4);
    const uint32_t zMax = *std::max_element(corners, corners + 4);
    uint32_t storedMin, storedMax;
    storedDepthRange(fb, x0, x1, y0, y1, storedMin, storedMax);
    // The pixel least likely to pass against the stored value most favourable to it, and the
    // other way round.
    const uint32_t worstZ = kNearerPasses ? zMax : zMin, bestZ = kNearerPasses ? zMin : zMax;
    const uint32_t worstStored = kNearerPasses ? storedMin : storedMax;
    const uint32_t bestStored = kNearerPasses ? storedMax : storedMin;
    if (!passesDepthCompare(kCompare, bestZ, bestStored)) return BlockDepthOutcome::AllFail;
    if (passesDepthCompare(kCompare, worstZ, worstStored)) return BlockDepthOutcome::AllPass;
    return BlockDepthOutcome::PerPixel;
  }
}

// Whether every pixel of the box's part of a block fails the early depth test, which must be an
// ordering: the pixel most likely to pass against the stored value most favourable to it. That
// pixel is a corner, the one the plane's slopes choose (the depths never decrease along a
// non-negative slope, see "Hidden blocks" above); the stored values are read in vector lanes, so
// the block's eight columns must be this thread's (BlockRows::storedWhole). blockDepthOutcome's
// AllFail, with one corner instead of four.
template <DepthCompare kCompare>
bool blockHidden(const TriangleSetup& setup, const BlockDepth& depth, const Framebuffer& fb, int bx, int by,
                 int x0, int x1, int y0, int y1) {
  constexpr bool kNearerPasses = nearerPasses(kCompare);
  const bool columnsRise = setup.zdx >= 0.0, rowsRise = setup.zdy >= 0.0;
  const int i = columnsRise == kNearerPasses ? x0 - bx : x1 - 1 - bx;
  const int j = rowsRise == kNearerPasses ? y0 - by : y1 - 1 - by;
  uint32_t storedMin, storedMax;
  blockColumnsDepthRange(fb.depthAt(bx, y0), fb.width(), y1 - y0, columnMask(x0 - bx, x1 - bx), storedMin,
                         storedMax);
  return !passesDepthCompare(kCompare, depth.at(i, j), kNearerPasses ? storedMax : storedMin);
}

// The walk of rasterizeTriangle for one early depth comparison (kEarly false: no early test),
// for a large triangle (a box of 32 x 32 pixels or more) or a small one, of kEdges edges (4: a
// convex quadrilateral, setupQuad).
template <bool kEarly, DepthCompare kCompare, bool kLarge, int kEdges>
void walkTriangle(const TriangleSetup& setup, FragmentSink& sink) {
  const PixelRect& box = setup.box;
  const PixelEdgeFunctions<kEdges> edges(setup);
  const Framebuffer* earlyDepth = setup.earlyDepth.buffer;
  HiddenBlockOdds* const odds = setup.hiddenBlockOdds;
  constexpr bool kOrdering = nearerPasses(kCompare) || fartherPasses(kCompare);
  const bool depthUsed = kEarly || setup.depthUsed;  // the early test reads it

  // What the block rows (block_rows.h) take from the triangle, the same for every block; each
  // block sets the rest. Edge k's step from column 0 of a block to column i is i * stepX[k].
  alignas(64) int64_t columnSteps[kEdges][kBlockSize];
  for (int k = 0; k < kEdges; ++k)
    for (int i = 0; i < kBlockSize; ++i) columnSteps[k][i] = edges.stepX[k] * i;
  BlockRows rows;
  rows.edgeCount = kEdges;
  for (int k = 0; k < kEdges; ++k) rows.stepY[k] = edges.stepY[k];
  rows.columnStep = columnSteps;
  rows.storedStride = earlyDepth != nullptr ? earlyDepth->width() : 0;
  rows.compare = kCompare;

  CoveredBlock block;
  const int firstBlockX = box.x0 & ~1, firstBlockY = box.y0;
  for (int by = firstBlockY; by < box.y1; by += kBlockSize) {
    const int y0 = std::max(by, box.y0), y1 = std::min(by + kBlockSize, box.y1);
    for (int bx = firstBlockX; bx < box.x1; bx += kBlockSize) {
      const int x0 = std::max(bx, box.x0), x1 = std::min(bx + kBlockSize, box.x1);
      if (edges.rejects(bx, by, kBlockSize, kBlockSize)) continue;
      bool accepted = true;
      for (int i = 0; i < kEdges; ++i)
        if (edges.minOver(i, bx, by, kBlockSize, kBlockSize) < 0) accepted = false;

      const int i0 = x0 - bx, i1 = x1 - bx;
      BlockDepth depth(setup, bx, by, i0, i1, y0 - by, y1 - by);
      const bool storedWhole = bx >= setup.privateRect.x0 && bx + kBlockSize <= setup.privateRect.x1;
      bool test = kEarly;
      if constexpr (kEarly) {
        if (kLarge || accepted) {
          const BlockDepthOutcome outcome =
              blockDepthOutcome<kCompare>(depth, *earlyDepth, bx, by, x0, x1, y0, y1);
          if (outcome == BlockDepthOutcome::AllFail) continue;
          test = outcome == BlockDepthOutcome::PerPixel;
        } else if constexpr (kOrdering) {
          // A small triangle's block: only the hidden test, and only where it has paid lately.
          if (odds != nullptr && storedWhole && odds->worthTesting()) {
            const bool hidden = blockHidden<kCompare>(setup, depth, *earlyDepth, bx, by, x0, x1, y0, y1);
            odds->record(hidden);
            if (hidden) continue;
          }
        }
      }
      if (depthUsed) depth.fillInterior();

      // Coverage and depth, row by row; a fragment that fails the early depth test goes no
      // further.
      for (int k = 0; k < kEdges; ++k) rows.rowStart[k] = edges.at(k, bx, y0);
      rows.accepted = accepted;
      rows.columns = columnMask(i0, i1);
      rows.firstRow = y0 - by;
      rows.endRow = y1 - by;
      rows.depthColumn = depthUsed ? depth.column : nullptr;
      rows.depthRow = depth.row;
      rows.stored = test ? earlyDepth->depthAt(bx, by) : nullptr;
      rows.storedWhole = storedWhole;
      block.bx = bx;
      block.by = by;
      const bool any = coverBlockRows(rows, block);
      if (any) sink.processTriangleBlock(setup, block);
    }
  }
}

}  // namespace

void emitBlockFragments(const TriangleSetup& setup, const CoveredBlock& block, FragmentSink& sink) {
  Fragment fragments[kBlockSize * kBlockSize];
  const int bx = block.bx, by = block.by;
  const double columnX0 = bx + 0.5, rowY0 = by + 0.5;  // centres of column/row 0
  const AttributePlanes& planes = setup.planes;
  const int varyingCount = setup.varyingCount;
  // q = 1/w (or 1), and p = varying / w, per column and row as above; a varying is p times
  // the reciprocal of q (one division a pixel, not one a varying: both exact IEEE operations in
  // double, rounded to float once at the end).
  double qColumn[kBlockSize], qRow[kBlockSize];
  double pColumn[kBlockSize][kMaxVaryings], pRow[kBlockSize][kMaxVaryings];
  unsigned columns = 0;  // the columns with a pixel in some row
  for (const uint8_t mask : block.rowMask) columns |= mask;
  for (int i = 0; i < kBlockSize; ++i) {
    if (!(columns & (1u << i))) continue;
    const double x = columnX0 + i;
    qColumn[i] = planes.invW0 + planes.invWdx * x;
    for (int k = 0; k < varyingCount; ++k) pColumn[i][k] = planes.a0[k] + planes.dx[k] * x;
  }
  int count = 0;
  for (int j = 0; j < kBlockSize; ++j) {
    const unsigned mask = block.rowMask[j];
    if (mask == 0) continue;
    const double y = rowY0 + j;
    qRow[j] = planes.invWdy * y;
    for (int k = 0; k < varyingCount; ++k) pRow[j][k] = planes.dy[k] * y;
    for (int i = 0; i < kBlockSize; ++i) {
      if (!(mask & (1u << i))) continue;
      Fragment& fragment = fragments[count++];
      fragment.x = bx + i;
      fragment.y = by + j;
      fragment.depth = block.depth[j][i];
      const double inverseQ = 1.0 / (qColumn[i] + qRow[j]);
      for (int k = 0; k < varyingCount; ++k)
        fragment.varyings[k] = static_cast<float>((pColumn[i][k] + pRow[j][k]) * inverseQ);
    }
  }

  FragmentBatch batch;
  batch.fragments = fragments;
  batch.count = count;
  batch.varyingCount = varyingCount;
  batch.frontFacing = setup.frontFacing;
  batch.planes = &setup.planes;
  batch.payload = setup.payload;
  sink.processFragments(batch);
}

void FragmentSink::processTriangleBlock(const TriangleSetup& setup, const CoveredBlock& block) {
  emitBlockFragments(setup, block, *this);
}

namespace {

// walkTriangle for the triangle's size: the blocks of a large triangle repay the look at their
// stored depths whole, a small one's are only tested for being hidden (hidden_block_odds.h).
template <bool kEarly, DepthCompare kCompare, int kEdges>
void walkBySize(const TriangleSetup& setup, FragmentSink& sink) {
  if constexpr (!kEarly) {
    walkTriangle<false, kCompare, true, kEdges>(setup, sink);  // without the early test the size decides nothing
  } else {
    const PixelRect& box = setup.box;
    if (box.x1 - box.x0 >= 4 * kBlockSize && box.y1 - box.y0 >= 4 * kBlockSize)
      return walkTriangle<true, kCompare, true, kEdges>(setup, sink);
    walkTriangle<true, kCompare, false, kEdges>(setup, sink);
  }
}

template <int kEdges>
void walkByDepthTest(const TriangleSetup& setup, FragmentSink& sink) {
  if (setup.earlyDepth.buffer == nullptr) return walkBySize<false, DepthCompare::Always, kEdges>(setup, sink);
  switch (setup.earlyDepth.compare) {
    case DepthCompare::Never: return;  // every fragment fails
    case DepthCompare::Less: return walkBySize<true, DepthCompare::Less, kEdges>(setup, sink);
    case DepthCompare::Equal: return walkBySize<true, DepthCompare::Equal, kEdges>(setup, sink);
    case DepthCompare::LessEqual: return walkBySize<true, DepthCompare::LessEqual, kEdges>(setup, sink);
    case DepthCompare::Greater: return walkBySize<true, DepthCompare::Greater, kEdges>(setup, sink);
    case DepthCompare::NotEqual: return walkBySize<true, DepthCompare::NotEqual, kEdges>(setup, sink);
    case DepthCompare::GreaterEqual:
      return walkBySize<true, DepthCompare::GreaterEqual, kEdges>(setup, sink);
    case DepthCompare::Always: return walkBySize<false, DepthCompare::Always, kEdges>(setup, sink);
  }
}

}  // namespace

void rasterizeTriangle(const TriangleSetup& setup, FragmentSink& sink) {
  if (setup.box.empty()) return;
  if (setup.edgeCount == 4) return walkByDepthTest<4>(setup, sink);
  walkByDepthTest<3>(setup, sink);
}

}  // namespace glass::raster
