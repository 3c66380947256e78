// GLASS_STATS=1: what the pipeline did in each frame of any program, counted stage by stage and
// printed to stderr when the frame is presented (glassWritePNG, glassGetColorBuffer and so a
// GLUT window's swap or single-buffered flush, an OSMesa buffer's glFlush/glFinish), then
// started again (docs/teaching.md, "Counting a frame").
//
// The counts follow the specification's order of stages:
//   vertices       vertices reaching primitive assembly (glVertex, array elements, evaluators)
//   primitives     points, lines and triangles assembled (a quad is two triangles, a polygon of
//                  n vertices n - 2, as glass assembles them)
//   culled         triangles glCullFace discarded (spec 2.6.1 facing, 3.5.1)
//   clipped away   primitives wholly outside the view volume or a user clip plane (spec 2.12)
//   clipped        primitives clipping cut, and the primitives it produced of them (a cut
//                  triangle is a polygon, rasterized as a fan of triangles)
//   fragments      fragments reaching the fragment stage, then those the scissor, alpha,
//                  stencil and depth tests rejected (spec 4.1), and those that passed every test
//   texel reads    texels the texture lookups of those fragments read: per level 1 for nearest,
//                  2, 4 or 8 for linear filtering of a 1D, 2D or 3D image (spec 3.8.8)
//
// With GLASS_STATS set, the draws go the general way (no early depth test in the rasterizer, no
// fast fragment kernels, the scissor test in the fragment stage), so that every fragment is seen
// by the stage that counts it; the pictures are the same bytes.
//
// GL_GLASS_pipeline_statistics (statistics_query.h) reads the same counts through query
// objects: a context gets them while GLASS_STATS is set or while a query is active, and only then.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "glass/raster/fragment.h"

namespace glass::gl {

struct Context;

// The counts as plain numbers, in the order of the report: what a query returns.
enum class PipelineCount {
  Vertices, Points, Lines, Triangles, Culled, ClippedAway, Clipped, ProducedByClipping,
  Fragments, ScissorRejected, AlphaRejected, StencilRejected, DepthRejected, Passed, TexelReads,
};
inline constexpr int kPipelineCountKinds = static_cast<int>(PipelineCount::TexelReads) + 1;
struct PipelineCounts {
  std::array<std::uint64_t, kPipelineCountKinds> values{};
  std::uint64_t operator[](PipelineCount count) const { return values[static_cast<int>(count)]; }
};

struct FrameStatistics {
  // Counted on the drawing thread.
  std::uint64_t vertices = 0;
  std::uint64_t points = 0, lines = 0, triangles = 0;
  std::uint64_t culled = 0, clippedAway = 0, clipped = 0, producedByClipping = 0;
  // Counted by the rasterizer's threads, a batch of fragments at a time.
  std::atomic<std::uint64_t> fragments{0};
  std::atomic<std::uint64_t> scissorRejected{0}, alphaRejected{0}, stencilRejected{0},
      depthRejected{0};
  std::atomic<std::uint64_t> passed{0};
  std::atomic<std::uint64_t> texelReads{0};
  std::uint64_t frame = 0;  // frames presented so far: the number of this one, counting from 0

  bool printsFrames = false;  // GLASS_STATS is set: each frame is reported and counted anew
  // While a query is active: what it gathered in the frames presented since it began, and the
  // counts of the current frame when it began (zero for the frames after).
  bool queryActive = false;
  PipelineCounts queryGathered, queryFrameStart;
};

// The counts so far (of the frame, with GLASS_STATS; since counting began, without).
PipelineCounts pipelineCountsOf(const FrameStatistics& statistics);

// A query begins: ctx counts from now on (attached now unless GLASS_STATS attached it). The
// queued drawing must be finished.
void beginQueryCounting(Context& ctx);
// The query ends: the counts since it began. Without GLASS_STATS, ctx stops counting. The queued
// drawing must be finished.
PipelineCounts endQueryCounting(Context& ctx);

// The fragment stage's counts for one batch, added to the frame's at the batch's end.
struct FragmentTally {
  std::uint64_t scissorRejected = 0, alphaRejected = 0, stencilRejected = 0, depthRejected = 0;
  std::uint64_t passed = 0, texelReads = 0;
};
void addFragmentTally(FrameStatistics& statistics, int fragments, const FragmentTally& tally);

// Reads GLASS_STATS (any value but empty or 0 turns it on) for a new context.
void attachFrameStatisticsFromEnvironment(Context& ctx);
void detachFrameStatistics(const Context& ctx);
// The counts of ctx's frame, or nullptr when GLASS_STATS is off: called once per draw.
FrameStatistics* frameStatisticsFor(const Context& ctx);

// Presentation: prints the frame's counts when anything was drawn since the last frame, and
// starts counting again. The queued drawing must be finished.
void reportFrameStatistics(Context& ctx);
// The report's text, for the report and for tests.
std::string formatFrameStatistics(const FrameStatistics& statistics);

// Texels a fragment's texture lookups read on every texture unit with a texture (see above).
std::uint64_t texelReadsOf(const Context& ctx, const raster::FragmentBatch& batch, int index);

}  // namespace glass::gl
