// Fragments, and the sink that receives them from the rasterizer.
//
// The rasterizer hands fragments over in batches (one batch per 8x8 block of a triangle, per batch
// of a line's runs, per point), so the per-fragment work behind the sink is reached through one indirect
// call per batch, never one per pixel.
#pragma once

#include <cstdint>

#include "glass/raster/vertex.h"

namespace glass::raster {

struct CoveredBlock;
struct LineRunBatch;
struct TriangleSetup;

// The depth buffer holds 24-bit unsigned integers: window z in [0, 1] maps to [0, 2^24 - 1].
inline constexpr uint32_t kDepthMax = (1u << 24) - 1u;

struct Fragment {
  int x, y;        // pixel coordinates (row 0 is the bottom row, as in GL)
  uint32_t depth;  // window depth, 24-bit fixed point, polygon offset included, clamped
  float varyings[kMaxVaryings];  // perspective-correct (or flat, as the pipeline set them up)
};

// Screen-space derivatives of the perspective-correct attributes of a triangle, for texture level
// of detail (spec section 3.8.8). For attribute a, with a/w and 1/w affine in window x and y:
//   a(x, y) = P(x, y) / Q(x, y),  P = a/w plane, Q = 1/w plane
//   da/dx   = (dP/dx * Q - P * dQ/dx) / Q^2
struct AttributePlanes {
  // For varying i: value/w at window (x, y) = a0[i] + dx[i] * x + dy[i] * y (x, y at pixel centres).
  double a0[kMaxVaryings], dx[kMaxVaryings], dy[kMaxVaryings];
  // 1/w at window (x, y) = invW0 + invWdx * x + invWdy * y.
  double invW0, invWdx, invWdy;
  // Exact derivatives d(varying i)/dx and d(varying i)/dy at the centre of pixel (px, py).
  void derivatives(int varying, int px, int py, double& ddx, double& ddy) const;
};

struct FragmentBatch {
  const Fragment* fragments = nullptr;
  int count = 0;
  int varyingCount = 0;                    // varyings[0 .. varyingCount) are valid
  bool frontFacing = true;                 // lines and points are front facing
  const AttributePlanes* planes = nullptr; // triangles only; null for lines and points
  const float* payload = nullptr;          // the triangle's TriangleSettings::payload, if any
};

class FragmentSink {
 public:
  virtual ~FragmentSink() = default;
  virtual void processFragments(const FragmentBatch& batch) = 0;
  // A triangle's 8x8 block after coverage and the early depth test (triangle_block.h). By
  // default the reference path, emitBlockFragments; a sink may override it with a kernel made
  // for its state that writes the same bytes.
  virtual void processTriangleBlock(const TriangleSetup& setup, const CoveredBlock& block);
  // Runs of a line segment (line_run.h). By default the reference path, emitLineRunFragments; a
  // sink may override it with a kernel made for its state that writes the same bytes.
  virtual void processLineRuns(const LineRunBatch& batch);
};

}  // namespace glass::raster
