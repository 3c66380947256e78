// Primitive assembly (spec 2.6.1): glBegin/glEnd bookkeeping that turns the stream of processed
// vertices into points, lines and triangles of the ten primitive types, each with the provoking
// vertex the specification names for flat shading (spec 2.13.7, table 2.6) and, for polygons,
// triangles and quads, the edge flags that say which edges are boundary edges (spec 2.6.2).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "vertex/pipeline_vertex.h"

namespace glass::gl {

struct PrimitiveAssembly {
  bool active = false;       // between glBegin and glEnd
  GLenum mode = GL_POINTS;
  int vertexCount = 0;       // vertices received since glBegin
  // The last vertices received, enough for strips, fans and quads; window[0] is the oldest.
  PipelineVertex window[4];
  PipelineVertex first;      // line loops and triangle fans keep their first vertex
  // GL_POLYGON and GL_QUADS hold their vertices until glEnd (primitive_assembly.cpp says why).
  std::vector<PipelineVertex> pending;
  bool pendingNeedsClipping = false;  // some pending vertex lies outside a clip plane
  // Immediate mode's vertices not yet through the vertex stage (gathered_vertices.h): whether
  // this glBegin gathers them, and the first gatheredCount rows of `gathered` (allocated at the
  // first gathered vertex, kept from then on).
  bool gathering = false;
  int gatheredCount = 0;
  uint64_t gatheredPrimitiveId = 0;  // newGatheredPrimitiveId of this glBegin (vertex_batch.h)
  // A glColor of this gathering glBegin left colour material's tracked parameters behind the
  // current colour; glEnd brings them up to date (gathered_vertices.h).
  bool colorMaterialDeferred = false;
  std::shared_ptr<struct VertexRows> gathered;
};

struct Context;

bool isPrimitiveMode(GLenum mode);

// glBegin's work once its errors are checked: prepares the per-draw state and starts assembling.
void beginPrimitive(Context& ctx, GLenum mode);
// A vertex from the vertex stage.
void assembleVertex(Context& ctx, const PipelineVertex& vertex);
// assembleVertex for vertices[0 .. count) in order, where the vertex stage has a batch of them
// at once: whole GL_TRIANGLES triangles are drawn straight from the array, without copying two
// of their vertices into the assembly's window first.
void assembleVertices(Context& ctx, const PipelineVertex* vertices, int count);
// The same for *vertices[0 .. count) (the post-transform cache's vertices of an indexed draw).
void assembleVertices(Context& ctx, const PipelineVertex* const* vertices, int count);
// glEnd's work: closes line loops, draws polygons and quads, drops an incomplete last primitive.
void endPrimitive(Context& ctx);

}  // namespace glass::gl
