// The rows of one 8x8 block of the triangle walk (triangle_rasterize.cpp): which pixel centres
// are inside the three edges (a quadrilateral's four), their depths, and the early depth test, the eight columns of a row
// as lanes of vectors. Compiled for every SIMD target (glass/raster/simd_target.h); each gives
// the reference's values to the bit (integers for the edges, one IEEE operation per lane for the
// depth), which the unit test block_rows compares pixel by pixel against a plain evaluation.
#pragma once

#include <cstddef>
#include <cstdint>

#include "glass/raster/depth_test.h"
#include "glass/raster/simd_target.h"
#include "glass/raster/triangle_block.h"

namespace glass::raster {

struct BlockRows {
  static constexpr int kSize = CoveredBlock::kSize;
  static constexpr int kMaxEdges = 4;
  // Edge k (k < edgeCount: 3, or 4 for a quadrilateral) at the centre of pixel (bx + i, by + j)
  // is rowStart[k] + columnStep[k][i] for row j = firstRow; each next row adds stepY[k].
  // columnStep[k][i] = i * (edge k's step in x).
  int edgeCount = 3;
  int64_t rowStart[kMaxEdges];
  const int64_t (*columnStep)[kSize];
  int64_t stepY[kMaxEdges];
  bool accepted;      // every centre of the block is inside all the edges: no coverage test
  unsigned columns;   // the columns of the triangle's box: bits [i0, i1)
  int firstRow, endRow;  // the rows of the triangle's box: [j0, j1)
  // The depth at the centre of pixel (bx + i, by + j) is depthValue(depthColumn[i] + depthRow[j]);
  // 0 when depthColumn is null (nothing reads it: TriangleSettings::depthUsed).
  const double* depthColumn;
  const double* depthRow;
  // The early depth test, unless `stored` is null: row j's stored depths from column bx are at
  // stored + j * storedStride. All eight are read when storedWhole (the block's columns are
  // private to this thread: TriangleSetup::privateRect), otherwise only the box's columns.
  const uint32_t* stored;
  ptrdiff_t storedStride;
  bool storedWhole;
  DepthCompare compare;
};

// Fills block.rowMask (rows outside [firstRow, endRow) empty) and, for the covered pixels of
// each row, block.depth; returns whether any pixel is covered and passed.
bool coverBlockRows(const BlockRows& rows, CoveredBlock& block);

// The smallest and largest of the stored depths of rowCount whole block rows (eight columns
// each) from `stored`, row r at stored + r * stride; rowCount >= 1.
void blockDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, uint32_t& lowest,
                     uint32_t& highest);
// The same over the columns of `columns` alone (bit i: column i; at least one). All eight
// columns of each row are read, so they must be this thread's to read.
void blockColumnsDepthRange(const uint32_t* stored, ptrdiff_t stride, int rowCount, unsigned columns,
                            uint32_t& lowest, uint32_t& highest);

// The same, by the copy compiled for `target` (which must run here: simdTargetRuns), for tests;
// the functions above use the chosen target's.
bool coverBlockRowsWith(SimdTarget target, const BlockRows& rows, CoveredBlock& block);
void blockDepthRangeWith(SimdTarget target, const uint32_t* stored, ptrdiff_t stride, int rowCount,
                         uint32_t& lowest, uint32_t& highest);
void blockColumnsDepthRangeWith(SimdTarget target, const uint32_t* stored, ptrdiff_t stride, int rowCount,
                                unsigned columns, uint32_t& lowest, uint32_t& highest);

}  // namespace glass::raster
