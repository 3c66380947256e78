#include "vertex/vertex_batch.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/context.h"
#include "fragment/fog_hooks.h"
#include "lighting/batched_lighting.h"
#include "lighting/lighting_equation.h"
#include "primitive/draw_pipeline.h"
#include "texture/texture_hooks.h"
#include "vertex/array_fetch.h"
#include "vertex/primitive_assembly.h"
#include "vertex/varyings.h"

namespace glass::gl {
namespace {

constexpr int K = kVertexBatch;  // elements per batch
// Post-transform cache entries (a power of two): direct-mapped by index.
constexpr int kCacheEntries = 256;

struct PostTransformCache {
  uint64_t tag[kCacheEntries];     // the index an entry holds, or kEmpty
  int pending[kCacheEntries];      // >= 0: the entry's vertex is batch vertex `pending`, not yet stored
  PipelineVertex vertex[kCacheEntries];
  static constexpr uint64_t kEmpty = ~uint64_t{0};
};

// Everything a batch works in, allocated once per thread and reused by every draw.
struct BatchWork {
  VertexRows in;
  float clip[4][K];
  float eye[4][K];
  LightingInput lighting;  // V and n of each vertex
  LitColorRows front, back;
  PipelineVertex out[K];
  // out[0 .. clearedCount) hold zero wherever processBatch does not write for the setup of the
  // gathering primitive `clearedFor` (0: none): see processVertexRows.
  uint64_t clearedFor = 0;
  int clearedCount = 0;
  PostTransformCache cache;
};

BatchWork& batchWork() {
  static thread_local std::unique_ptr<BatchWork> work = std::make_unique<BatchWork>();
  return *work;
}

constexpr float kPointDefaults[4] = {0.0f, 0.0f, 0.0f, 1.0f};
constexpr float kColorDefaults[4] = {0.0f, 0.0f, 0.0f, 1.0f};

template <int N>
void repeat(const float* value, int count, float (&rows)[N][K]) {
  for (int c = 0; c < N; ++c) std::fill(rows[c], rows[c] + count, value[c]);
}

template <int N>
void fetchOrRepeat(const ClientArray& array, bool enabled, bool normalized, const float* defaults,
                   const float* current, const int* indices, int first, int count,
                   float (&rows)[N][K]) {
  if (!enabled) return repeat(current, count, rows);
  float* rowPointers[N];
  for (int c = 0; c < N; ++c) rowPointers[c] = rows[c];
  fetchArrayRows(array, normalized, defaults, N, indices, first, count, rowPointers);
}

// readElement for every element of the batch, in rows.
void fetchBatch(const Context& ctx, const ArrayElementLayout& layout, const VertexStageSetup& s,
                const int* indices, int first, int count, VertexRows& in) {
  const ArrayState& a = ctx.arrays;
  const CurrentState& current = ctx.current;
  fetchOrRepeat(a.vertex, true, false, kPointDefaults, nullptr, indices, first, count, in.vertex);
  fetchOrRepeat(a.color, layout.color, true, kColorDefaults, current.color, indices, first, count,
                in.color);
  if (s.needEyeNormal) {
    fetchOrRepeat(a.normal, layout.normal, true, kPointDefaults, current.normal, indices, first,
                  count, in.normal);
  }
  if (s.secondaryColor) {
    fetchOrRepeat(a.secondaryColor, layout.secondaryColor, true, kColorDefaults,
                  current.secondaryColor, indices, first, count, in.secondaryColor);
  }
  if (s.fog) {
    fetchOrRepeat(a.fogCoord, layout.fogCoord, false, kPointDefaults, &current.fogCoord, indices,
                  first, count, in.fogCoord);
  }
  for (int u = 0; u < s.textureUnits; ++u) {
    fetchOrRepeat(a.texCoord[u], layout.texCoord[u], false, kPointDefaults, current.texCoord[u],
                  indices, first, count, in.texCoord[u]);
  }
  for (int i = 0; i < count; ++i) {
    if (!layout.edgeFlag) {
      in.edgeFlag[i] = current.edgeFlag;
      continue;
    }
    const long long index = indices != nullptr ? indices[i] : static_cast<long long>(first) + i;
    in.edgeFlag[i] = static_cast<const unsigned char*>(a.edgeFlag.pointer)[index * arrayElementStride(a.edgeFlag)] != 0;
  }
}

// out = M * in for every vertex: transformVector4's operations, a row at a time.
void transformRows(const Matrix4& matrix, const float (&in)[4][K], int count, float (&out)[4][K]) {
  const float* m = matrix.m;
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < count; ++i)
      out[r][i] = m[r] * in[0][i] + m[4 + r] * in[1][i] + m[8 + r] * in[2][i] + m[12 + r] * in[3][i];
}

// The eye-space normals of processVertex: n_o^T M^-1, then normalized or rescaled.
void transformNormals(const VertexStageSetup& s, const float (&in)[3][K], int count,
                      float (&normal)[3][K]) {
  const Matrix4& inv = s.modelviewInverse;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < count; ++i)
      normal[j][i] = in[0][i] * inv.at(0, j) + in[1][i] * inv.at(1, j) + in[2][i] * inv.at(2, j);
  if (s.normalize) {
    for (int i = 0; i < count; ++i) {
      const float length = std::sqrt(normal[0][i] * normal[0][i] + normal[1][i] * normal[1][i] +
                                     normal[2][i] * normal[2][i]);
      if (length > 0.0f) {
        for (int j = 0; j < 3; ++j) normal[j][i] /= length;
      }
    }
  } else if (s.rescaleNormal) {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < count; ++i) normal[j][i] *= s.rescaleFactor;
  }
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

// processVertex for the `count` elements of `in`, into work.out[0 .. count). With colorPerVertex,
// colour material takes each element's colour (in.color); otherwise the stored material already
// tracks the current colour.
void processBatch(const Context& ctx, bool colorPerVertex, const VertexStageSetup& s,
                  const VertexRows& in, int count, BatchWork& work) {
  transformRows(s.modelviewProjection, in.vertex, count, work.clip);
  if (s.needEyePosition) transformRows(s.modelview, in.vertex, count, work.eye);
  LightingInput& lighting = work.lighting;
  lighting.count = count;
  if (s.needEyeNormal) transformNormals(s, in.normal, count, lighting.normal);

  // The vertices' outcodes a batch at a time, unless user clip planes need each vertex's
  // distances (computed below).
  const bool frustumOnly = ctx.draw->clipsToFrustumOnly();
  unsigned frustumCodes[K];
  if (frustumOnly) raster::frustumOutcodes(work.clip[0], work.clip[1], work.clip[2], work.clip[3], count, frustumCodes);

  const bool twoSided = s.twoSided;
  if (s.lightPerVertex) {
    // eyePointFromHomogeneous, a row at a time.
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < count; ++i) lighting.point[c][i] = eyeCoordinateFromHomogeneous(work.eye[c][i], work.eye[3][i]);
    lighting.color = colorPerVertex ? in.color : nullptr;
    const LightingState& l = ctx.lighting;
    lightBatch(l, kFrontMaterial, false, lighting, work.front);
    if (l.model.twoSide) lightBatch(l, kBackMaterial, true, lighting, work.back);
  }

  for (int i = 0; i < count; ++i) {
    PipelineVertex& out = work.out[i];
    raster::ClipVertex& v = out.clip;
    for (int r = 0; r < 4; ++r) v.clip[r] = work.clip[r][i];
    out.edgeFlag = in.edgeFlag[i];
    float* varyings = v.varyings;
    if (s.lightPerVertex) {
      // Lit colours come clamped to [0, 1] (LitColorRows), as the reference path's clamp leaves
      // them.
      for (int c = 0; c < 4; ++c) {
        varyings[varying::kPrimaryColor + c] = work.front.primary[c][i];
        varyings[varying::kSecondaryColor + c] = work.front.secondary[c][i];
      }
      if (twoSided) {
        // Without GL_LIGHT_MODEL_TWO_SIDE twoSided is false, so work.back is always fresh here.
        for (int c = 0; c < 4; ++c) {
          out.backColor[c] = work.back.primary[c][i];
          out.backSecondary[c] = work.back.secondary[c][i];
        }
      }
    } else {
      for (int c = 0; c < 4; ++c) {
        varyings[varying::kPrimaryColor + c] = clamp01(in.color[c][i]);
        varyings[varying::kSecondaryColor + c] = 0.0f;
      }
      if (s.secondaryColor) {
        for (int c = 0; c < 3; ++c) varyings[varying::kSecondaryColor + c] = clamp01(in.secondaryColor[c][i]);
      }
    }

    float eye[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    if (s.needEyePosition) {
      for (int r = 0; r < 4; ++r) eye[r] = work.eye[r][i];
    }
    if (s.fog) varyings[varying::kFogCoordinate] = fogCoordinate(ctx, eye, in.fogCoord[0][i]);
    if (s.texturing) {
      float texCoord[kTextureUnitCount][4];
      for (int u = 0; u < s.textureUnits; ++u)
        for (int c = 0; c < 4; ++c) texCoord[u][c] = in.texCoord[u][c][i];
      const float object[4] = {in.vertex[0][i], in.vertex[1][i], in.vertex[2][i], in.vertex[3][i]};
      const float normal[3] = {lighting.normal[0][i], lighting.normal[1][i], lighting.normal[2][i]};
      computeTexCoords(ctx, s.textureUnits, texCoord, object, eye, normal, varyings);
    }
    if (s.eyeNormalVarying) {
      const float w = eye[3] != 0.0f ? eye[3] : 1.0f;
      for (int c = 0; c < 3; ++c) {
        varyings[varying::kEyePosition + c] = eye[c] / w;
        varyings[varying::kEyeNormal + c] = lighting.normal[c][i];
      }
    }
    std::fill(std::begin(v.userClipDistance), std::end(v.userClipDistance), 0.0f);
    for (unsigned planes = s.clipPlaneMask; planes != 0; planes &= planes - 1) {
      const int p = std::countr_zero(planes);
      const float* plane = s.clipPlanes[p];
      v.userClipDistance[p] = plane[0] * eye[0] + plane[1] * eye[1] + plane[2] * eye[2] + plane[3] * eye[3];
    }
    out.clipCode = frustumOnly ? frustumCodes[i] : ctx.draw->clipCodeOf(v);
  }
}

// Processes and assembles elements first .. first + count - 1, a batch at a time.
void drawSequential(Context& ctx, const ArrayElementLayout& layout, const VertexStageSetup& s,
                    int first, int count, BatchWork& work) {
  for (int start = 0; start < count; start += K) {
    const int n = std::min(K, count - start);
    fetchBatch(ctx, layout, s, nullptr, first + start, n, work.in);
    processBatch(ctx, layout.color, s, work.in, n, work);
    assembleVertices(ctx, work.out, n);
  }
}

// Processes and assembles indices[0 .. count), through the post-transform cache: a batch of
// positions looks its indices up; those not cached are fetched and processed together, then the
// positions are assembled in order, then the new vertices are stored in the cache. (An entry a
// position of the batch found stays untouched until the batch is assembled.)
void drawIndexed(Context& ctx, const ArrayElementLayout& layout, const VertexStageSetup& s,
                 const int* indices, int count, BatchWork& work) {
  PostTransformCache& cache = work.cache;
  std::fill(std::begin(cache.tag), std::end(cache.tag), PostTransformCache::kEmpty);
  std::fill(std::begin(cache.pending), std::end(cache.pending), -1);
  const PipelineVertex* positions[K];
  int missIndex[K], missEntry[K];
  for (int start = 0; start < count; start += K) {
    const int n = std::min(K, count - start);
    int misses = 0;
    for (int p = 0; p < n; ++p) {
      const int index = indices[start + p];
      const uint64_t tag = static_cast<uint32_t>(index);
      const int entry = static_cast<int>(tag & (kCacheEntries - 1));
      if (cache.tag[entry] == tag) {
        const int pending = cache.pending[entry];
        positions[p] = pending >= 0 ? &work.out[pending] : &cache.vertex[entry];
        continue;
      }
      cache.tag[entry] = tag;
      cache.pending[entry] = misses;
      missIndex[misses] = index;
      missEntry[misses] = entry;
      positions[p] = &work.out[misses];
      ++misses;
    }
    if (misses > 0) {
      fetchBatch(ctx, layout, s, missIndex, 0, misses, work.in);
      processBatch(ctx, layout.color, s, work.in, misses, work);
    }
    assembleVertices(ctx, positions, n);
    for (int m = 0; m < misses; ++m) {
      const int entry = missEntry[m];
      if (cache.pending[entry] != m) continue;  // a later miss of the batch took the entry
      cache.vertex[entry] = work.out[m];
      cache.pending[entry] = -1;
    }
  }
}

}  // namespace

uint64_t newGatheredPrimitiveId() {
  static std::atomic<uint64_t> lastId{0};
  return lastId.fetch_add(1, std::memory_order_relaxed) + 1;
}

void processVertexRows(Context& ctx, const VertexRows& rows, int count, uint64_t primitiveId) {
  if (count <= 0) return;
  const VertexStageSetup& s = ctx.draw->vertexSetup();
  BatchWork& work = batchWork();
  // The slots processBatch does not write must read as zero, as in processVertex's fresh vertex.
  // Which slots it writes depends only on the setup, which stays the same from glBegin to glEnd,
  // so an output vertex cleared for an earlier batch of the same primitive is still zero there:
  // only outputs this primitive has not used yet are cleared (a long glBegin/glEnd clears 64
  // vertices once instead of once per batch). The id is unique across contexts and threads, so
  // outputs another draw on this thread wrote in between are cleared again.
  if (work.clearedFor != primitiveId) {
    work.clearedFor = primitiveId;
    work.clearedCount = 0;
  }
  if (work.clearedCount < count) {
    std::fill(work.out + work.clearedCount, work.out + count, PipelineVertex{});
    work.clearedCount = count;
  }
  processBatch(ctx, true, s, rows, count, work);
  assembleVertices(ctx, work.out, count);
}

void drawArrayElementsBatched(Context& ctx, const ArrayElementLayout& layout, const int* indices,
                              int first, int count) {
  if (count <= 0) return;
  const VertexStageSetup& s = ctx.draw->vertexSetup();
  BatchWork& work = batchWork();
  // Slots a draw does not write read as zero, as in processVertex's fresh vertex.
  std::fill(std::begin(work.out), std::end(work.out), PipelineVertex{});
  work.clearedFor = 0;  // this draw's setup may write slots a gathering primitive does not
  if (indices != nullptr) {
    drawIndexed(ctx, layout, s, indices, count, work);
  } else {
    drawSequential(ctx, layout, s, first, count, work);
  }
  // The current attributes after the draw: those the last element set (applyElement without its
  // glVertex), including the material colour material tracks.
  ArrayElementLayout attributes = layout;
  attributes.vertex = false;
  ArrayElementValues last;
  readElement(ctx.arrays, attributes, indices != nullptr ? indices[count - 1] : first + count - 1, last);
  applyElement(ctx, attributes, last);
}

}  // namespace glass::gl
