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

namespace {

// value[0 .. N) into column i of rows. The values are all read before any is stored: as far as
// the compiler knows the rows might overlap the current attributes, and storing each value as it
// is read made it check that for every vertex.
template <int N>
void storeColumn(const float* value, int i, float (&rows)[N][kVertexBatch]) {
  float copy[N];
  for (int k = 0; k < N; ++k) copy[k] = value[k];
  for (int k = 0; k < N; ++k) rows[k][i] = copy[k];
}

}  // namespace

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
  storeColumn(object, i, rows.vertex);
  storeColumn(c.color, i, rows.color);
  rows.edgeFlag[i] = c.edgeFlag;
  if (s.needEyeNormal) storeColumn(c.normal, i, rows.normal);
  if (s.secondaryColor) storeColumn(c.secondaryColor, i, rows.secondaryColor);
  if (s.fog) rows.fogCoord[0][i] = c.fogCoord;
  for (int u = 0; u < s.textureUnits; ++u) storeColumn(c.texCoord[u], i, rows.texCoord[u]);
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
