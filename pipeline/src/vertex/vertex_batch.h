// The vertex fast path (docs/pipeline.md, "The vertex fast path"): glDrawArrays and
// glDrawElements run the vertex stage over batches of up to 64 elements instead of one glVertex
// at a time. A batch reads each enabled array once per batch (array_fetch.h), transforms the
// positions and normals and lights the vertices in loops over the batch, one row of values per
// component (batched_lighting.h), and hands the vertices to primitive assembly in order.
// glDrawElements keeps the vertices it has processed in a post-transform cache keyed by index, so
// an index that comes again soon (a mesh's shared vertex) is transformed and lit once.
//
// The reference path is drawArrayElements's loop: applyElement for each element, which sets the
// current attributes and calls processVertex (vertex_stage.h). The fast path evaluates the same
// float operations in the same order, so it writes the same bytes; GLASS_FAST_PATHS=0 turns it off
// and tests/image/fast_paths.cmake compares the two on every image test.
#pragma once

#include <cstdint>

#include "lighting/batched_lighting.h"
#include "texture/texture_units.h"
#include "vertex/array_draw.h"

namespace glass::gl {

struct Context;

// Vertices per batch: as many as batched lighting takes at once.
inline constexpr int kVertexBatch = kLightingBatch;

// The attributes of up to kVertexBatch vertices, one row per component, as a batch reads them.
// Rows the vertex stage does not need (VertexStageSetup: normals without lighting, unused
// texture units, ...) need not be filled.
struct VertexRows {
  float vertex[4][kVertexBatch];
  float color[4][kVertexBatch];
  float normal[3][kVertexBatch];
  float secondaryColor[3][kVertexBatch];
  float fogCoord[1][kVertexBatch];
  float texCoord[kTextureUnitCount][4][kVertexBatch];
  bool edgeFlag[kVertexBatch];
};

// The vertices of a glDrawArrays (indices null: elements first .. first + count - 1) or
// glDrawElements (indices[0 .. count)), between beginCommand and endCommand, with
// layout.vertex set and no display list being compiled. Afterwards the current attributes are
// those the last element set, as after the reference path.
void drawArrayElementsBatched(Context& ctx, const ArrayElementLayout& layout, const int* indices,
                              int first, int count);

// A new id for one gathering glBegin/glEnd (never 0, never repeated, whatever the context or
// thread), for processVertexRows.
uint64_t newGatheredPrimitiveId();

// The vertex stage for vertices 0 .. count - 1 of `rows` (count <= kVertexBatch), between
// beginCommand and endCommand, handing them to primitive assembly in order: immediate mode's
// gathered vertices (gathered_vertices.h). Colour material takes each vertex's colour. The
// current attributes are left as they were. primitiveId (newGatheredPrimitiveId, taken at
// glBegin) names the primitive the rows belong to: its batches share output vertices.
void processVertexRows(Context& ctx, const VertexRows& rows, int count, uint64_t primitiveId);

}  // namespace glass::gl
