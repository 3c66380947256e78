#include "pixels/raster_position.h"

#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "glass/raster/clip.h"
#include "lighting/lighting_hooks.h"
#include "primitive/viewport_transform.h"
#include "select/render_mode.h"
#include "vertex/varyings.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {

void setRasterPosition(Context& ctx, const float object[4]) {
  RasterPositionState& r = ctx.rasterPosition;

  // The raster position is processed by the vertex stage like any vertex, with what that stage
  // computes only when primitives need it switched on: the lit front colour whenever lighting is
  // on (also with per-fragment shading), texture coordinates always (spec 2.13).
  VertexStageSetup setup;
  prepareVertexStage(ctx, setup);
  setup.lightPerVertex = lightingEnabled(ctx);
  setup.phong = false;
  setup.twoSided = false;
  setup.texturing = true;
  setup.textureUnits = kTextureUnitCount;  // every unit's raster texture coordinates (spec 2.13)
  setup.needEyePosition = true;
  if (!setup.needEyeNormal) {
    // The normal is needed for sphere-map texture generation.
    invert(setup.modelview, setup.modelviewInverse);
    const Matrix4& inv = setup.modelviewInverse;
    const float lengthSquared = inv.at(2, 0) * inv.at(2, 0) + inv.at(2, 1) * inv.at(2, 1) +
                                inv.at(2, 2) * inv.at(2, 2);
    setup.rescaleFactor = lengthSquared > 0.0f ? 1.0f / std::sqrt(lengthSquared) : 1.0f;
    setup.needEyeNormal = true;
  }
  setup.varyingCount =
      std::max(setup.varyingCount, varying::countForTextureUnits(kTextureUnitCount));

  PipelineVertex vertex{};
  processVertex(ctx, setup, object, vertex);
  const float* clip = vertex.clip.clip;

  // Spec 2.13: the raster position is clipped like a point; outside any plane it becomes invalid
  // and the rest of the raster state keeps its values. So it does, like a point, where it has no
  // window position (w_c = 0, or coordinates that are not finite; see toWindow).
  raster::ClipSettings clipping;
  clipping.userPlaneMask = setup.clipPlaneMask;
  raster::WindowVertex window;
  if (!raster::pointInside(vertex.clip, clipping) ||
      !toWindow(makeViewportTransform(ctx.transform.viewport, ctx.transform.depthNear,
                                      ctx.transform.depthFar),
                vertex.clip, 0, window)) {
    r.valid = false;
    return;
  }
  r.window[0] = window.x;
  r.window[1] = window.y;
  r.window[2] = window.z;
  r.window[3] = clip[3];
  r.valid = true;

  // Spec 2.13: the raster distance is the distance from the eye to the position, or with
  // GL_FOG_COORDINATE_SOURCE GL_FOG_COORDINATE the current fog coordinate (OpenGL 1.4).
  float eye[4];
  transformVector4(setup.modelview, object, eye);
  const float w = eye[3] != 0.0f ? eye[3] : 1.0f;
  r.distance = ctx.fog.coordinateSource == GL_FOG_COORDINATE
                   ? ctx.current.fogCoord
                   : std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]) / std::fabs(w);

  const float* varyings = vertex.clip.varyings;
  for (int k = 0; k < 4; ++k) {
    r.color[k] = varyings[varying::kPrimaryColor + k];
    r.secondaryColor[k] = varyings[varying::kSecondaryColor + k];
  }
  for (int u = 0; u < kTextureUnitCount; ++u) {
    for (int k = 0; k < 4; ++k) r.texCoord[u][k] = varyings[varying::texCoordSlot(u) + k];
  }

  if (ctx.renderMode.mode == GL_SELECT) recordHit(ctx, r.window[2]);
}

void setWindowPosition(Context& ctx, float x, float y, float z) {
  RasterPositionState& r = ctx.rasterPosition;
  const double n = ctx.transform.depthNear, f = ctx.transform.depthFar;
  r.window[0] = x;
  r.window[1] = y;
  r.window[2] = static_cast<float>(n + std::clamp(static_cast<double>(z), 0.0, 1.0) * (f - n));
  r.window[3] = 1.0f;
  r.valid = true;
  // Spec 2.13 (glWindowPos): the current fog coordinate with GL_FOG_COORDINATE_SOURCE
  // GL_FOG_COORDINATE, otherwise 0.
  r.distance = ctx.fog.coordinateSource == GL_FOG_COORDINATE ? ctx.current.fogCoord : 0.0f;
  for (int k = 0; k < 4; ++k) {
    r.color[k] = std::clamp(ctx.current.color[k], 0.0f, 1.0f);
  }
  for (int u = 0; u < kTextureUnitCount; ++u) {
    for (int k = 0; k < 4; ++k) r.texCoord[u][k] = ctx.current.texCoord[u][k];
  }
  r.secondaryColor[0] = r.secondaryColor[1] = r.secondaryColor[2] = 0.0f;
  r.secondaryColor[3] = 1.0f;

  if (ctx.renderMode.mode == GL_SELECT) recordHit(ctx, r.window[2]);
}

}  // namespace glass::gl
