#include "primitive/smooth_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glass::gl {
namespace {

float saturate(float v) { return std::clamp(v, 0.0f, 1.0f); }

// A corner: the vertex's depth, 1/w and varyings at window (x, y).
raster::WindowVertex corner(const raster::WindowVertex& v, float x, float y, int varyingCount) {
  raster::WindowVertex c;
  c.x = x;
  c.y = y;
  c.z = v.z;
  c.invW = v.invW;
  std::copy(v.varyings, v.varyings + varyingCount, c.varyings);
  return c;
}

}  // namespace

float SmoothLineCoverage::coverage(float x, float y) const {
  const float rx = x - midX, ry = y - midY;
  const float along = rx * dirX + ry * dirY;
  const float across = ry * dirX - rx * dirY;
  const float acrossCoverage = saturate(halfWidth - std::fabs(across));
  const float alongCoverage =
      saturate(halfLength - std::fabs(along)) * std::min(length / halfLength, 1.0f);
  return acrossCoverage * alongCoverage;
}

bool makeSmoothLine(const raster::WindowVertex& a, const raster::WindowVertex& b, float width,
                    int framebufferHeight, int varyingCount, SmoothLineShape& shape) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0.0f) || !std::isfinite(length)) return false;
  varyingCount = std::clamp(varyingCount, 0, raster::kMaxVaryings);
  shape.length = length;
  shape.dirX = dx / length;
  shape.dirY = dy / length;
  shape.midX = 0.5f * (a.x + b.x);
  shape.midY = 0.5f * (a.y + b.y);
  shape.halfWidth = width <= 1.0f ? 1.0f : 0.5f * width + 0.5f;
  shape.halfLength = 0.5f * length + 0.5f;

  // The corners as Mesa computes them, in rows numbered downwards from the framebuffer's top
  // (Y = height - y), turned back to GL's rows at the end.
  const float top = static_cast<float>(framebufferHeight);
  const float ya = top - a.y, yb = top - b.y;
  const float downDy = yb - ya;
  const float c = dx / length, s = downDy / length;
  const float w = shape.halfWidth, l = 0.5f;
  shape.corners[0] = corner(b, b.x + (l * c - w * s), top - (yb + (l * s + w * c)), varyingCount);
  shape.corners[1] =
      corner(a, a.x + (-l * c - -w * s), top - (ya + (-l * s + -w * c)), varyingCount);
  shape.corners[2] = corner(a, a.x + (-l * c - w * s), top - (ya + (-l * s + w * c)), varyingCount);
  shape.corners[3] = corner(b, b.x + (l * c - -w * s), top - (yb + (l * s + -w * c)), varyingCount);
  return true;
}

float SmoothPointCoverage::coverage(float fx, float fy) const {
  const float s = (fx - x) / radius, t = (fy - y) / radius;
  const float d = s * s + t * t;
  if (d > 1.0f) return -1.0f;
  // Mesa's selection: (1 - d) / (1 - k) inside k, 1 in the ring (see smooth_coverage.h).
  const float inverse = 1.0f / radius;
  const float k = 1.0f - 2.0f * inverse + inverse * inverse;
  return k >= d ? (1.0f / (1.0f - k)) * (1.0f - d) : 1.0f;
}

float smoothPointRadius(float size, bool perVertexSize) {
  if (perVertexSize) return 0.5f * size;
  return size <= 2.0f ? 1.0f : 0.5f * size;
}

void makeSmoothPoint(const raster::WindowVertex& v, float radius, int framebufferHeight,
                     int varyingCount, SmoothPointShape& shape) {
  varyingCount = std::clamp(varyingCount, 0, raster::kMaxVaryings);
  shape.x = v.x;
  shape.y = v.y;
  shape.radius = radius;
  // Mesa's corners in rows numbered from the top: (x - r, Y - r), (x + r, Y - r), (x + r, Y + r),
  // (x - r, Y + r), so its diagonal runs from the upper left to the lower right in GL's rows.
  const float top = static_cast<float>(framebufferHeight);
  const float y = top - v.y;
  shape.corners[0] = corner(v, v.x - radius, top - (y - radius), varyingCount);
  shape.corners[1] = corner(v, v.x + radius, top - (y - radius), varyingCount);
  shape.corners[2] = corner(v, v.x + radius, top - (y + radius), varyingCount);
  shape.corners[3] = corner(v, v.x - radius, top - (y + radius), varyingCount);
}

template <class Coverage>
void CoverageFilter<Coverage>::processFragments(const raster::FragmentBatch& batch) {
  if (batch.payload == nullptr) return;  // not a shape's triangle: nothing to weigh it by
  Coverage shape;
  std::memcpy(static_cast<void*>(&shape), batch.payload, sizeof shape);  // trivially copyable floats
  constexpr int kChunk = 64;
  raster::Fragment kept[kChunk];
  float coverage[kChunk];
  for (int first = 0; first < batch.count; first += kChunk) {
    const int end = std::min(batch.count, first + kChunk);
    int count = 0;
    for (int i = first; i < end; ++i) {
      const raster::Fragment& f = batch.fragments[i];
      const float c =
          shape.coverage(static_cast<float>(f.x) + 0.5f, static_cast<float>(f.y) + 0.5f);
      if (c < 0.0f) continue;
      kept[count] = f;
      coverage[count++] = c;
    }
    if (count == 0) continue;
    raster::FragmentBatch out = batch;
    out.fragments = kept;
    out.count = count;
    next_.processFragments(out, coverage);
  }
}

template <class Coverage>
void CoverageFilter<Coverage>::processTriangleBlock(const raster::TriangleSetup& setup,
                                                   const raster::CoveredBlock& block) {
  if (next_.shadeBlock(setup, block, Coverage::kKernelCoverage)) return;
  raster::FragmentSink::processTriangleBlock(setup, block);  // emitBlockFragments, then processFragments
}

template class CoverageFilter<SmoothLineCoverage>;
template class CoverageFilter<SmoothPointCoverage>;

}  // namespace glass::gl
