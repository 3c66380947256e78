// One 8x8 block of a triangle after coverage and the early depth test: what the triangle walk
// (triangle_rasterize.cpp) hands to a fragment sink, before any varying is interpolated.
//
// The sink's default treatment (FragmentSink::processTriangleBlock) is the reference path:
// interpolate every varying of every pixel into a Fragment and pass the block on as one
// FragmentBatch. A sink may instead run a kernel specialised for its state on the block (the
// pipeline's fast paths, docs/pipeline.md), which must write the same bytes.
#pragma once

#include <cstdint>

namespace glass::raster {

struct TriangleSetup;
class FragmentSink;

struct CoveredBlock {
  static constexpr int kSize = 8;
  int bx = 0, by = 0;  // the block's lower-left pixel; bx is even (2x2 quads stay in one block)
  // Bit i of rowMask[j]: pixel (bx + i, by + j) is covered and passed the early depth test.
  uint8_t rowMask[kSize] = {};
  // The window depth (24-bit, bias included, clamped) of those pixels, [j][i].
  uint32_t depth[kSize][kSize];
};

// The reference path: interpolates the varyings of the block's pixels at their centres and
// hands them to sink.processFragments as one batch.
void emitBlockFragments(const TriangleSetup& setup, const CoveredBlock& block, FragmentSink& sink);

}  // namespace glass::raster
