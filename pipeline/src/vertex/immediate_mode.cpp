#include "vertex/immediate_mode.h"

#include "core/context.h"
#include "lighting/lighting_hooks.h"
#include "primitive/draw_pipeline.h"
#include "vertex/gathered_vertices.h"
#include "vertex/primitive_assembly.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {

void beginCommand(Context& ctx, GLenum mode) {
  if (ctx.assembly.active) return recordError(ctx, GL_INVALID_OPERATION);
  if (!isPrimitiveMode(mode)) return recordError(ctx, GL_INVALID_ENUM);
  beginPrimitive(ctx, mode);
  startGathering(ctx);
}

void endCommand(Context& ctx) {
  if (!ctx.assembly.active) return recordError(ctx, GL_INVALID_OPERATION);
  endPrimitive(ctx);
}

namespace {

// A vertex through the vertex stage at once (the reference path). Out of line so that the usual
// glVertex, which is gathered, does not pay for the stack frame and clearing of a PipelineVertex.
[[gnu::noinline]] void processAndAssembleVertex(Context& ctx, const float object[4]) {
  PipelineVertex vertex{};
  processVertex(ctx, ctx.draw->vertexSetup(), object, vertex);
  assembleVertex(ctx, vertex);
}

}  // namespace

void vertexCommand(Context& ctx, float x, float y, float z, float w) {
  if (!ctx.assembly.active) return;
  const float object[4] = {x, y, z, w};
  if (gatherVertex(ctx, object)) return;
  processAndAssembleVertex(ctx, object);
}

void colorCommand(Context& ctx, float r, float g, float b, float a) {
  float* c = ctx.current.color;
  c[0] = r;
  c[1] = g;
  c[2] = b;
  c[3] = a;
  onCurrentColorChanged(ctx);
}

void normalCommand(Context& ctx, float x, float y, float z) {
  float* n = ctx.current.normal;
  n[0] = x;
  n[1] = y;
  n[2] = z;
}

void texCoordCommand(Context& ctx, int unit, const float coords[4]) {
  float* tc = ctx.current.texCoord[unit];
  for (int k = 0; k < 4; ++k) tc[k] = coords[k];
}

void edgeFlagCommand(Context& ctx, bool flag) { ctx.current.edgeFlag = flag; }

void secondaryColorCommand(Context& ctx, float r, float g, float b) {
  float* c = ctx.current.secondaryColor;
  c[0] = r;
  c[1] = g;
  c[2] = b;
  c[3] = 1.0f;
}

void fogCoordCommand(Context& ctx, float c) { ctx.current.fogCoord = c; }

void rectCommand(Context& ctx, float x1, float y1, float x2, float y2) {
  if (ctx.assembly.active) return recordError(ctx, GL_INVALID_OPERATION);
  beginPrimitive(ctx, GL_POLYGON);
  vertexCommand(ctx, x1, y1, 0.0f, 1.0f);
  vertexCommand(ctx, x2, y1, 0.0f, 1.0f);
  vertexCommand(ctx, x2, y2, 0.0f, 1.0f);
  vertexCommand(ctx, x1, y2, 0.0f, 1.0f);
  endPrimitive(ctx);
}

}  // namespace glass::gl
