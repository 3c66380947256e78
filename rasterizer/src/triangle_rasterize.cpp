// Triangle coverage: walks the setup's bounding box in 8x8 blocks aligned to multiples of 8 (so a
// later step can hand whole tiles to threads), and hands each block's fragments to the sink in one
// batch.
//
// Fill rule. A pixel is covered when its centre is strictly inside all three edges, or exactly on
// an edge that owns its centres. Of two triangles sharing an edge exactly one owns it: the edge
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
// hidden, and the divisions of perspective-correct interpolation are the costliest part.
#include <algorithm>

#include "glass/raster/depth_value.h"
#include "edge_functions.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/triangle.h"

namespace glass::raster {
namespace {

constexpr int kBlockSize = 8;

struct BlockFragments {
  Fragment fragments[kBlockSize * kBlockSize];
  int count = 0;
};

// The columns [x0, x1) and rows [y0, y1) of a block whose lower-left pixel is (bx, by).
struct BlockSpan {
  int bx, by, x0, x1, y0, y1;
};

// The depth plane at the block's pixel centres, split as described at the top of the file.
struct BlockDepth {
  double column[kBlockSize], row[kBlockSize];

  BlockDepth(const TriangleSetup& setup, const BlockSpan& span) {
    for (int i = span.x0 - span.bx; i < span.x1 - span.bx; ++i)
      column[i] = setup.z0 + setup.zdx * (span.bx + i + 0.5);
    for (int j = span.y0 - span.by; j < span.y1 - span.by; ++j)
      row[j] = setup.zdy * (span.by + j + 0.5);
  }
};

// Interpolates the varyings of the block's fragments (whose position and depth are set), then
// hands them to the sink.
void interpolateAndEmit(const TriangleSetup& setup, const BlockSpan& span, BlockFragments& block,
                        FragmentSink& sink) {
  const double columnX0 = span.bx + 0.5, rowY0 = span.by + 0.5;  // centres of column/row 0
  const int kept = block.count;
  block.count = 0;
  const AttributePlanes& planes = setup.planes;
  const int varyingCount = setup.varyingCount;
  // q = 1/w (or 1), and p = varying / w, per column and row as above; a varying is p / q.
  double qColumn[kBlockSize], qRow[kBlockSize];
  double pColumn[kBlockSize][kMaxVaryings], pRow[kBlockSize][kMaxVaryings];
  for (int i = span.x0 - span.bx; i < span.x1 - span.bx; ++i) {
    const double x = columnX0 + i;
    qColumn[i] = planes.invW0 + planes.invWdx * x;
    for (int k = 0; k < varyingCount; ++k) pColumn[i][k] = planes.a0[k] + planes.dx[k] * x;
  }
  for (int j = span.y0 - span.by; j < span.y1 - span.by; ++j) {
    const double y = rowY0 + j;
    qRow[j] = planes.invWdy * y;
    for (int k = 0; k < varyingCount; ++k) pRow[j][k] = planes.dy[k] * y;
  }
  for (int f = 0; f < kept; ++f) {
    Fragment& fragment = block.fragments[f];
    const int i = fragment.x - span.bx, j = fragment.y - span.by;
    const double q = qColumn[i] + qRow[j];
    for (int k = 0; k < varyingCount; ++k)
      fragment.varyings[k] = static_cast<float>((pColumn[i][k] + pRow[j][k]) / q);
  }

  FragmentBatch batch;
  batch.fragments = block.fragments;
  batch.count = kept;
  batch.varyingCount = varyingCount;
  batch.frontFacing = setup.frontFacing;
  batch.planes = &setup.planes;
  sink.processFragments(batch);
}

}  // namespace

void rasterizeTriangle(const TriangleSetup& setup, FragmentSink& sink) {
  const PixelRect& box = setup.box;
  if (box.empty()) return;
  const PixelEdgeFunctions edges(setup);
  const Framebuffer* earlyDepth = setup.earlyDepth.buffer;
  const DepthCompare compare = setup.earlyDepth.compare;

  BlockFragments block;
  const int firstBlockX = box.x0 & ~(kBlockSize - 1), firstBlockY = box.y0 & ~(kBlockSize - 1);
  for (int by = firstBlockY; by < box.y1; by += kBlockSize) {
    const int y0 = std::max(by, box.y0), y1 = std::min(by + kBlockSize, box.y1);
    for (int bx = firstBlockX; bx < box.x1; bx += kBlockSize) {
      const int x0 = std::max(bx, box.x0), x1 = std::min(bx + kBlockSize, box.x1);
      if (edges.rejects(bx, by, kBlockSize, kBlockSize)) continue;
      bool accepted = true;
      for (int i = 0; i < 3; ++i)
        if (edges.minOver(i, bx, by, kBlockSize, kBlockSize) < 0) accepted = false;

      // Coverage and depth, row by row. A covered pixel's depth is computed at once, and a
      // fragment that fails the early depth test goes no further.
      const BlockSpan span{bx, by, x0, x1, y0, y1};
      const BlockDepth depth(setup, span);
      for (int y = y0; y < y1; ++y) {
        const double zRow = depth.row[y - by];
        const uint32_t* stored = earlyDepth ? earlyDepth->depthAt(0, y) : nullptr;
        auto cover = [&](int x) {
          const uint32_t z = depthValue(depth.column[x - bx] + zRow);
          if (stored && !passesDepthCompare(compare, z, stored[x])) return;
          Fragment& f = block.fragments[block.count++];
          f.x = x;
          f.y = y;
          f.depth = z;
        };
        if (accepted) {
          for (int x = x0; x < x1; ++x) cover(x);
          continue;
        }
        int64_t e0 = edges.at(0, x0, y), e1 = edges.at(1, x0, y), e2 = edges.at(2, x0, y);
        for (int x = x0; x < x1; ++x) {
          if ((e0 | e1 | e2) >= 0) cover(x);
          e0 += edges.stepX[0];
          e1 += edges.stepX[1];
          e2 += edges.stepX[2];
        }
      }
      if (block.count > 0) interpolateAndEmit(setup, span, block, sink);
    }
  }
}

}  // namespace glass::raster
