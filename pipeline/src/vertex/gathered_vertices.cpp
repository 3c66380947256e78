#include "vertex/gathered_vertices.h"

#include <memory>

#include "core/context.h"
#include "core/fast_paths.h"
#include "lighting/lighting_hooks.h"
#include "primitive/draw_pipeline.h"
#include "vertex/vertex_batch.h"

namespace glass::gl {

void startGathering(Context& ctx) {
  const VertexStageSetup& s = ctx.draw->vertexSetup();
  PrimitiveAssembly& pa = ctx.assembly;
  pa.gatheredCount = 0;
  pa.gathering = fastPathsEnabled() && s.trace == nullptr;
  if (pa.gathering) pa.gatheredPrimitiveId = newGatheredPrimitiveId();
}

bool gatherVertex(Context& ctx, const float object[4]) {
  PrimitiveAssembly& pa = ctx.assembly;
  if (!pa.gathering) return false;
  if (!pa.gathered) pa.gathered = std::make_shared<VertexRows>();
  // The rows the batched stage reads (vertex_batch.cpp, processBatch); the others are left as an
  // earlier vertex wrote them and are not read.
  const VertexStageSetup& s = ctx.draw->vertexSetup();
  const CurrentState& c = ctx.current;
  VertexRows& rows = *pa.gathered;
  const int i = pa.gatheredCount++;
  for (int k = 0; k < 4; ++k) {
    rows.vertex[k][i] = object[k];
    rows.color[k][i] = c.color[k];
  }
  rows.edgeFlag[i] = c.edgeFlag;
  if (s.needEyeNormal)
    for (int k = 0; k < 3; ++k) rows.normal[k][i] = c.normal[k];
  if (s.secondaryColor)
    for (int k = 0; k < 3; ++k) rows.secondaryColor[k][i] = c.secondaryColor[k];
  if (s.fog) rows.fogCoord[0][i] = c.fogCoord;
  for (int u = 0; u < s.textureUnits; ++u)
    for (int k = 0; k < 4; ++k) rows.texCoord[u][k][i] = c.texCoord[u][k];
  if (pa.gatheredCount == kVertexBatch) flushGatheredVertices(ctx);
  return true;
}

void flushGatheredVertices(Context& ctx) {
  PrimitiveAssembly& pa = ctx.assembly;
  const int count = pa.gatheredCount;
  if (count == 0) return;
  pa.gatheredCount = 0;
  processVertexRows(ctx, *pa.gathered, count, pa.gatheredPrimitiveId);
}

bool deferColorMaterial(Context& ctx) {
  PrimitiveAssembly& pa = ctx.assembly;
  if (!pa.active || !pa.gathering) return false;
  pa.colorMaterialDeferred = true;
  return true;
}

void finishGathering(Context& ctx) {
  flushGatheredVertices(ctx);
  PrimitiveAssembly& pa = ctx.assembly;
  pa.gathering = false;
  if (pa.colorMaterialDeferred) {
    pa.colorMaterialDeferred = false;
    onCurrentColorChanged(ctx);  // not gathering any more: applies the current colour now
  }
}

}  // namespace glass::gl
