#include "primitive/viewport_transform.h"

#include <cmath>

#include "core/transform_state.h"

namespace glass::gl {

ViewportTransform makeViewportTransform(const Viewport& v, double depthNear, double depthFar) {
  ViewportTransform t;
  t.scale[0] = static_cast<float>(v.width * 0.5);
  t.scale[1] = static_cast<float>(v.height * 0.5);
  t.scale[2] = static_cast<float>((depthFar - depthNear) * 0.5);
  t.offset[0] = static_cast<float>(v.x + v.width * 0.5);
  t.offset[1] = static_cast<float>(v.y + v.height * 0.5);
  t.offset[2] = static_cast<float>((depthFar + depthNear) * 0.5);
  return t;
}

bool toWindow(const ViewportTransform& t, const raster::ClipVertex& in, int varyingCount,
              raster::WindowVertex& out) {
  if (in.clip[3] == 0.0f) return false;
  const float invW = 1.0f / in.clip[3];
  out.x = in.clip[0] * invW * t.scale[0] + t.offset[0];
  out.y = in.clip[1] * invW * t.scale[1] + t.offset[1];
  out.z = in.clip[2] * invW * t.scale[2] + t.offset[2];
  out.invW = invW;
  for (int i = 0; i < varyingCount; ++i) out.varyings[i] = in.varyings[i];
  return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z) &&
         std::isfinite(invW);
}

}  // namespace glass::gl
