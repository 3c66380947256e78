// A vertex leaving the vertex stage: clip coordinates and varyings, ready for primitive assembly
// and clipping, plus what the primitive stages still need (back-face colours, the edge flag).
#pragma once

#include "glass/raster/vertex.h"

namespace glass::gl {

// PipelineVertex::clipCode when the vertex's outcode has not been computed.
inline constexpr unsigned kClipCodeUnknown = ~0u;

struct PipelineVertex {
  raster::ClipVertex clip;
  // raster::outcode of `clip` under the draw's clip settings, computed once per vertex by the
  // batched vertex path (DrawPipeline::clipCodeOf) for the primitives that share the vertex; or
  // kClipCodeUnknown, and the primitive stages compute it.
  unsigned clipCode = kClipCodeUnknown;
  // With two-sided lighting, the colours for back-facing primitives: the primitive stage copies
  // them over the front colours once it knows the facing (spec 2.13.1).
  float backColor[4];
  float backSecondary[4];
  bool edgeFlag;  // this vertex starts a boundary edge (spec 2.6.2)
};

}  // namespace glass::gl
