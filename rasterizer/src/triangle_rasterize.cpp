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
#include <algorithm>

#include "depth_value.h"
#include "glass/raster/triangle.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

constexpr int kBlockSize = 8;
constexpr int kBlockLog2 = 3;

struct BlockFragments {
  Fragment fragments[kBlockSize * kBlockSize];
  int count = 0;
};

// Fills depth and varyings of the batch's fragments from the planes, then hands it over.
void shadeAndEmit(const TriangleSetup& setup, BlockFragments& block, FragmentSink& sink) {
  const AttributePlanes& planes = setup.planes;
  const int varyingCount = setup.varyingCount;
  for (int f = 0; f < block.count; ++f) {
    Fragment& fragment = block.fragments[f];
    const double x = fragment.x + 0.5, y = fragment.y + 0.5;
    fragment.depth = depthValue(setup.z0 + setup.zdx * x + setup.zdy * y);
    const double q = planes.invW0 + planes.invWdx * x + planes.invWdy * y;
    for (int k = 0; k < varyingCount; ++k) {
      const double p = planes.a0[k] + planes.dx[k] * x + planes.dy[k] * y;
      fragment.varyings[k] = static_cast<float>(p / q);
    }
  }
  FragmentBatch batch;
  batch.fragments = block.fragments;
  batch.count = block.count;
  batch.varyingCount = varyingCount;
  batch.frontFacing = setup.frontFacing;
  batch.planes = &setup.planes;
  sink.processFragments(batch);
  block.count = 0;
}

}  // namespace

void rasterizeTriangle(const TriangleSetup& setup, FragmentSink& sink) {
  const PixelRect& box = setup.box;
  if (box.empty()) return;

  // Per edge: the step of the biased edge value from one pixel centre to the next, and the extra
  // amount that takes a block's first pixel centre to its corner of largest and smallest value.
  int64_t stepX[3], stepY[3], biasedC[3], toMax[3], toMin[3];
  for (int i = 0; i < 3; ++i) {
    const int64_t a = setup.edgeA[i], b = setup.edgeB[i];
    const bool ownsCentres = a > 0 || (a == 0 && b > 0);
    biasedC[i] = setup.edgeC[i] + (ownsCentres ? 0 : -1);
    stepX[i] = a * kSubpixelOne;
    stepY[i] = b * kSubpixelOne;
    const int64_t spanX = stepX[i] * (kBlockSize - 1), spanY = stepY[i] * (kBlockSize - 1);
    toMax[i] = std::max<int64_t>(spanX, 0) + std::max<int64_t>(spanY, 0);
    toMin[i] = std::min<int64_t>(spanX, 0) + std::min<int64_t>(spanY, 0);
  }
  auto edgeAt = [&](int i, int px, int py) {
    return setup.edgeA[i] * (px * kSubpixelOne + kSubpixelHalf) +
           setup.edgeB[i] * (py * kSubpixelOne + kSubpixelHalf) + biasedC[i];
  };

  BlockFragments block;
  const int firstBlockX = box.x0 & ~(kBlockSize - 1), firstBlockY = box.y0 & ~(kBlockSize - 1);
  for (int by = firstBlockY; by < box.y1; by += kBlockSize) {
    const int y0 = std::max(by, box.y0), y1 = std::min(by + kBlockSize, box.y1);
    for (int bx = firstBlockX; bx < box.x1; bx += kBlockSize) {
      const int x0 = std::max(bx, box.x0), x1 = std::min(bx + kBlockSize, box.x1);
      int64_t origin[3];
      bool rejected = false, accepted = true;
      for (int i = 0; i < 3; ++i) {
        origin[i] = edgeAt(i, bx, by);
        if (origin[i] + toMax[i] < 0) rejected = true;
        if (origin[i] + toMin[i] < 0) accepted = false;
      }
      if (rejected) continue;

      if (accepted) {
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) {
            Fragment& f = block.fragments[block.count++];
            f.x = x;
            f.y = y;
          }
      } else {
        for (int y = y0; y < y1; ++y) {
          int64_t e0 = origin[0] + stepY[0] * (y - by) + stepX[0] * (x0 - bx);
          int64_t e1 = origin[1] + stepY[1] * (y - by) + stepX[1] * (x0 - bx);
          int64_t e2 = origin[2] + stepY[2] * (y - by) + stepX[2] * (x0 - bx);
          for (int x = x0; x < x1; ++x) {
            if ((e0 | e1 | e2) >= 0) {
              Fragment& f = block.fragments[block.count++];
              f.x = x;
              f.y = y;
            }
            e0 += stepX[0];
            e1 += stepX[1];
            e2 += stepX[2];
          }
        }
      }
      if (block.count > 0) shadeAndEmit(setup, block, sink);
    }
  }
}

}  // namespace glass::raster
