#include "primitive/point_parameters.h"

#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryPointParameterState(const Context& ctx, GLenum pname, StateValue& v) {
  const RasterState& r = ctx.raster;
  switch (pname) {
    case GL_POINT_SIZE_MIN: v.setFloats({r.pointSizeMin}); return true;
    case GL_POINT_SIZE_MAX: v.setFloats({r.pointSizeMax}); return true;
    case GL_POINT_FADE_THRESHOLD_SIZE: v.setFloats({r.pointFadeThreshold}); return true;
    case GL_POINT_DISTANCE_ATTENUATION:
      v.setFloats(r.pointDistanceAttenuation, 3);
      return true;
    default: return false;
  }
}

bool pointSizeAttenuated(const RasterState& r) {
  const float* a = r.pointDistanceAttenuation;
  return a[0] != 1.0f || a[1] != 0.0f || a[2] != 0.0f || r.pointSizeMin != 0.0f ||
         r.pointSizeMax != kMaxPointSize;
}

float derivedPointSize(const RasterState& r, float d) {
  const float* a = r.pointDistanceAttenuation;
  const float denominator = a[0] + a[1] * d + a[2] * d * d;
  float size = r.pointSize;
  if (denominator > 0.0f) size *= std::sqrt(1.0f / denominator);
  return std::clamp(size, r.pointSizeMin, std::max(r.pointSizeMin, r.pointSizeMax));
}

}  // namespace glass::gl
