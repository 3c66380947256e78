// Immediate mode through the vertex fast path (docs/pipeline.md, "The vertex fast path"). Between
// glBegin and glEnd, glVertex stores the vertex with the current attributes it would be
// processed with into rows of a batch (vertex_batch.h, VertexRows) instead of running the vertex
// stage on it at once; the gathered vertices go through the batched vertex stage and on to
// primitive assembly 64 at a time, and whenever something is about to change what the vertex
// stage reads: at glEnd and before glMaterial. Nothing can look at the vertices in between (no
// other command is allowed inside glBegin/glEnd), so the primitives are the same; the batched
// stage evaluates the same float operations as processVertex, so they are the same bytes.
//
// Whether a glBegin gathers is decided when it starts: not when the fast paths are off
// (GLASS_FAST_PATHS=0), nor while the teaching vertex trace waits for a vertex
// (GLASS_TRACE_VERTEX follows one vertex through processVertex). With colour material on, the
// batched stage lights each vertex with its own colour in place of the tracked parameters, which
// is what the reference path's stored material holds: there the tracked parameters always equal
// the current colour (glColor copies it in, glMaterial leaves them alone, glPopAttrib copies it
// in again). A gathering glBegin/glEnd copies it in once, at glEnd (deferColorMaterial below).
#pragma once

#include "core/context.h"

namespace glass::gl {

// At glBegin, once the primitive has started: whether its vertices are gathered.
void startGathering(Context& ctx);

// glVertex's work inside glBegin/glEnd: true when the vertex was gathered, false when it must go
// through the vertex stage at once.
bool gatherVertex(Context& ctx, const float object[4]);

// Runs the gathered vertices through the vertex stage and primitive assembly, in order.
void flushGatheredVertices(Context& ctx);

// Colour material inside a gathering glBegin/glEnd. Copying each glColor into the tracked
// material parameters costs more than the rest of the glColor, and nothing reads them before
// glEnd: the gathered vertices are lit with their own colour, glMaterial leaves tracked parameters
// alone, and every command that could read or replace them (glGetMaterial, glPushAttrib,
// glColorMaterial, glEnable ...) is an error inside glBegin/glEnd. So a colour change there
// only marks the tracked parameters stale (true: deferred; false: not gathering, apply now), and
// glEnd applies the current colour once, which leaves the same material as applying every one.
// Inline: every glColor asks.
inline bool deferColorMaterial(Context& ctx) {
  PrimitiveAssembly& pa = ctx.assembly;
  if (!pa.active || !pa.gathering) return false;
  pa.colorMaterialDeferred = true;
  return true;
}

// glEnd's part: the last gathered vertices through the vertex stage, then the deferred colour
// material applied.
void finishGathering(Context& ctx);

}  // namespace glass::gl
