// Fog (OpenGL 1.5 specification, section 3.10): the fragment's colour is blended towards the fog
// colour by a factor f that falls with the distance c from the eye:
//   GL_LINEAR  f = (end - c) / (end - start)
//   GL_EXP     f = exp(-density * c)
//   GL_EXP2    f = exp(-(density * c)^2)
//   C' = f * C + (1 - f) * C_fog  for R, G and B (alpha is left alone), f clamped to [0, 1].
//
// Where f is computed: the specification lets an implementation compute it per vertex and
// interpolate it, or per fragment. glass does what Mesa's llvmpipe does: the vertex stage stores
// the eye distance c = |z_e| per vertex (the specification allows |z_e| for the distance), the
// rasterizer interpolates c perspective-correctly, and f is computed per fragment from the
// interpolated c. So fog is exact across large triangles, even for EXP and EXP2, whose factor is
// not linear in c.
#include "fragment/fog_hooks.h"

#include <cmath>

#include "core/context.h"
#include "core/state_value.h"
#include "vertex/varyings.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl {

bool setFogCapability(Context& ctx, GLenum cap, bool enabled) {
  if (cap == GL_COLOR_SUM) {
    ctx.fog.colorSum = enabled;
    return true;
  }
  if (cap != GL_FOG) return false;
  ctx.fog.enabled = enabled;
  return true;
}

bool getFogCapability(const Context& ctx, GLenum cap, bool& enabled) {
  if (cap == GL_COLOR_SUM) {
    enabled = ctx.fog.colorSum;
    return true;
  }
  if (cap != GL_FOG) return false;
  enabled = ctx.fog.enabled;
  return true;
}

bool queryFogState(const Context& ctx, GLenum pname, StateValue& value) {
  const FogState& f = ctx.fog;
  switch (pname) {
    case GL_FOG_MODE: value.setIntegers({double(f.mode)}); return true;
    case GL_FOG_DENSITY: value.setFloats({f.density}); return true;
    case GL_FOG_START: value.setFloats({f.start}); return true;
    case GL_FOG_END: value.setFloats({f.end}); return true;
    case GL_FOG_INDEX: value.setFloats({f.index}); return true;
    case GL_FOG_COLOR: value.setColors(f.color, 4); return true;
    case GL_FOG_COORDINATE_SOURCE: value.setIntegers({double(f.coordinateSource)}); return true;
    default: return false;
  }
}

bool fogEnabled(const Context& ctx) { return ctx.fog.enabled; }

// With GL_FOG_COORDINATE as the source, the vertex's glFogCoord value instead; its magnitude,
// as Mesa takes it (a fog coordinate of -5 fogs like 5).
float fogCoordinate(const Context& ctx, const float eyePosition[4], float vertexFogCoord) {
  if (ctx.fog.coordinateSource == GL_FOG_COORDINATE) return std::fabs(vertexFogCoord);
  return std::fabs(eyePosition[2]);
}

// The fog factor f for eye distance c, clamped to [0, 1].
float fogFactor(const FogState& fog, float c) {
  float f = 1.0f;
  switch (fog.mode) {
    case GL_LINEAR: {
      // With start == end the ratio is undefined; like Mesa, use a scale of 1 then.
      const float range = fog.end - fog.start;
      f = range != 0.0f ? (fog.end - c) / range : fog.end - c;
      break;
    }
    case GL_EXP: f = portable::exp(-fog.density * c); break;
    case GL_EXP2: {
      const float dc = fog.density * c;
      f = portable::exp(-(dc * dc));
      break;
    }
    default: break;
  }
  return f < 0.0f ? 0.0f : (f > 1.0f ? 1.0f : f);
}

void applyFog(const FogState& fog, const raster::Fragment& fragment, float color[4]) {
  const float f = fogFactor(fog, fragment.varyings[varying::kFogCoordinate]);
  for (int i = 0; i < 3; ++i) color[i] = f * color[i] + (1.0f - f) * fog.color[i];
}

}  // namespace glass::gl
