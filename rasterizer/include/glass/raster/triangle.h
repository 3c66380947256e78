// Triangle rasterization by fixed-point half-space edge functions.
//
// Window coordinates are snapped to 8 sub-pixel bits; a pixel is covered when its centre
// (x + 0.5, y + 0.5) lies inside all three edges, with the top-left rule deciding centres exactly
// on an edge, so triangles sharing an edge never both draw, nor both miss, a pixel on it. The rule
// is stated for rows that run downwards, as in raster memory; in GL's bottom-up window coordinates
// it means left and bottom edges own their centres, which is also what Mesa draws.
// Setup (edge equations, bounding box, attribute planes) is separate from coverage, which walks
// 8x8 blocks with trivial accept and reject.
#pragma once

#include <cstdint>

#include "glass/raster/depth_test.h"
#include "glass/raster/fragment.h"
#include "glass/raster/vertex.h"

namespace glass::raster {

struct HiddenBlockOdds;  // hidden_block_odds.h (the rasterizer's own)

// The tiled rasterizer keeps one copy of these per draw, not per triangle: a field added here must
// also be compared in TileScene::drawSettingsFor (or, if it changes from triangle to triangle of a
// draw as frontFacing and depthBias do, kept in the scene's triangle record).
struct TriangleSettings {
  PixelRect bounds;            // framebuffer intersected with the scissor box
  int varyingCount = 0;
  bool perspectiveCorrect = true;  // false: varyings affine in screen space
  // Added to window z before the depth test: polygon offset (spec 3.5.5), computed by the
  // pipeline as factor * max|dz/dx|,|dz/dy| + units * r, in window-depth units ([0, 1] range).
  double depthBias = 0.0;
  bool frontFacing = true;     // passed through to the fragment batches
  EarlyDepthTest earlyDepth;   // off by default (depth_test.h)
  // Whether anything reads the fragments' depth (the depth test is on). When not, the walk
  // neither interpolates it nor computes the block's depth plane, and gives every fragment 0.
  bool depthUsed = true;
  // Values the sink reads with every fragment of the triangle (FragmentBatch::payload): the
  // coverage shape of an antialiased line or point. payloadCount floats from payload, at most
  // kMaxTrianglePayload; the tiled rasterizer keeps a copy with the queued triangle.
  const float* payload = nullptr;
  int payloadCount = 0;
};

inline constexpr int kMaxTrianglePayload = 8;

struct TriangleSetup {
  // Edge functions E_i(x, y) = A_i * x + B_i * y + C_i in 24.8 fixed point (x, y are window
  // coordinates times 256), oriented so the interior is E_i > 0 (or E_i == 0 on an edge that owns
  // its centres: A_i > 0, or A_i == 0 and B_i > 0). A triangle has three; a convex quadrilateral
  // (setupQuad) four.
  static constexpr int kMaxEdges = 4;
  int64_t edgeA[kMaxEdges], edgeB[kMaxEdges], edgeC[kMaxEdges];
  int edgeCount = 3;
  PixelRect box;                 // pixels that can be covered, already clipped to the bounds
  double z0, zdx, zdy;           // window depth plane at pixel centres, bias included
  AttributePlanes planes;
  int varyingCount;
  bool perspectiveCorrect;
  bool frontFacing;
  EarlyDepthTest earlyDepth;
  bool depthUsed = true;  // TriangleSettings::depthUsed
  // The pixels of the framebuffer that nothing else reads or writes while the triangle is drawn
  // (the tiled rasterizer's tile): the early depth test may read a whole block row of stored
  // depths inside it, beyond the box. Empty: only the box's pixels are read.
  PixelRect privateRect;
  // Where the walk keeps the odds of finding a small triangle's block hidden (the tile's, in the
  // tiled rasterizer); null: such blocks are not tested.
  HiddenBlockOdds* hiddenBlockOdds = nullptr;
  const float* payload = nullptr;  // TriangleSettings::payload
  // Signed area in window coordinates (positive: counter-clockwise), for facing and culling.
  double signedArea;
};

// Returns false (and draws nothing) for a degenerate triangle or one outside the bounds.
bool setupTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                   const TriangleSettings& settings, TriangleSetup& setup);
// The first, cheap step of setupTriangle alone: sets the edge functions and the box (clipped to
// the bounds) exactly as it does, and returns what it returns, without the planes (the
// divisions): what the tiled rasterizer needs to bin a triangle, whose planes its tiles compute.
bool setupTriangleEdges(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                        const PixelRect& bounds, TriangleSetup& setup);

// A convex quadrilateral v0 v1 v2 v3 (its corners in order round it, either way), drawn as the
// two triangles (v0, v1, v2) and (v2, v3, v0) would be drawn in one pass, with the depth and
// attribute planes of the first (setupTriangle(v0, v1, v2)'s, to the bit) for all its pixels:
// for a quadrilateral whose values are one plane, as an antialiased line's or point's rectangle
// (smooth_coverage.h), whose triangles share every 8x8 block along their diagonal. A pixel is
// covered when its centre is inside the four edges, by the triangles' fill rule: exactly the
// pixels of the two triangles (the rule decides a centre on v0 or v2 for the two edges there as
// for the triangles' four: a convex corner is owned when both its edges own their centres).
// Returns false, drawing nothing, when the snapped corners do not make a strictly convex
// quadrilateral (quadIsConvex: then draw the two triangles) or the box is empty.
bool setupQuad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3,
               const TriangleSettings& settings, TriangleSetup& setup);
// setupQuad's edges and box alone (as setupTriangleEdges): what binning needs.
bool setupQuadEdges(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                    const WindowVertex& v3, const PixelRect& bounds, TriangleSetup& setup);
// Whether the snapped corners make a strictly convex quadrilateral of two non-degenerate
// triangles, so that setupQuad may draw it (within the rasterizable coordinates).
bool quadIsConvex(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3);

// Emits every covered pixel of the setup to the sink, one batch per 8x8 block.
void rasterizeTriangle(const TriangleSetup& setup, FragmentSink& sink);

// Signed area (twice the area) of a window-space triangle: positive when counter-clockwise.
double windowSignedArea(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c);

}  // namespace glass::raster
