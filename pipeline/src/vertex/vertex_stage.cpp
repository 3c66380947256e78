#include "vertex/vertex_stage.h"

#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "fragment/fog_hooks.h"
#include "lighting/lighting_hooks.h"
#include "teaching/teaching_view.h"
#include "teaching/vertex_trace.h"
#include "texture/texture_hooks.h"
#include "vertex/varyings.h"

namespace glass::gl {

namespace {

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

void copy4Clamped(const float* in, float* out) {
  for (int i = 0; i < 4; ++i) out[i] = clamp01(in[i]);
}

}  // namespace

void prepareVertexStage(const Context& ctx, VertexStageSetup& s) {
  const TransformState& t = ctx.transform;
  s.modelview = t.modelview.top();
  s.modelviewProjection = multiply(t.projection.top(), s.modelview);

  const bool lighting = lightingEnabled(ctx);
  s.phong = lighting && ctx.raster.shadeModel == GL_PHONG_WIN;
  s.eyeNormalVarying = s.phong || teachingViewNeedsEyeNormals(ctx);
  s.lightPerVertex = lighting && !s.phong;
  s.twoSided = s.lightPerVertex && twoSidedLighting(ctx);
  s.texturing = texturingEnabled(ctx);
  s.textureUnits = s.texturing ? textureUnitsInUse(ctx) : 0;
  s.fog = fogEnabled(ctx);
  s.normalize = t.normalize;
  s.rescaleNormal = t.rescaleNormal && !t.normalize;

  s.clipPlaneMask = t.clipPlaneEnabled;
  for (int i = 0; i < raster::kMaxUserClipPlanes; ++i) {
    for (int j = 0; j < 4; ++j) s.clipPlanes[i][j] = static_cast<float>(t.clipPlanes[i][j]);
  }

  s.trace = vertexTraceFor(ctx);
  // A traced vertex shows its eye position and normal whether the state needs them or not.
  s.needEyeNormal = lighting || s.texturing || s.eyeNormalVarying || s.trace;
  s.needEyePosition = s.needEyeNormal || s.fog || s.clipPlaneMask != 0;
  if (s.needEyeNormal) {
    invert(s.modelview, s.modelviewInverse);
    // Spec 2.11.3: f = 1 / sqrt(m31^2 + m32^2 + m33^2), m from the inverse modelview matrix.
    const Matrix4& inv = s.modelviewInverse;
    const float lengthSquared = inv.at(2, 0) * inv.at(2, 0) + inv.at(2, 1) * inv.at(2, 1) +
                                inv.at(2, 2) * inv.at(2, 2);
    s.rescaleFactor = lengthSquared > 0.0f ? 1.0f / std::sqrt(lengthSquared) : 1.0f;
  }

  int count = varying::kCountPrimary;
  // OpenGL 1.4: without lighting, GL_COLOR_SUM adds glSecondaryColor (spec 2.14, 3.9).
  s.secondaryColor = !lighting && ctx.fog.colorSum;
  if ((lighting && separateSpecularColor(ctx)) || s.secondaryColor) {
    count = varying::kCountSecondary;
  }
  if (s.fog) count = varying::kCountFog;
  if (s.texturing) count = varying::kCountTexture;
  if (s.eyeNormalVarying) count = varying::kCountPhong;
  if (s.texturing) count = std::max(count, varying::countForTextureUnits(s.textureUnits));
  s.varyingCount = count;
}

void processVertex(const Context& ctx, const VertexStageSetup& s, const float object[4],
                   PipelineVertex& out) {
  raster::ClipVertex& v = out.clip;
  transformVector4(s.modelviewProjection, object, v.clip);
  out.clipCode = kClipCodeUnknown;  // `out` may be a slot an earlier vertex used
  out.edgeFlag = ctx.current.edgeFlag;

  float eye[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  if (s.needEyePosition) transformVector4(s.modelview, object, eye);

  float normal[3] = {0.0f, 0.0f, 1.0f};
  if (s.needEyeNormal) {
    // n_e = (nx ny nz) * M^-1 restricted to the upper-left 3x3 (spec 2.11.3).
    const float* n = ctx.current.normal;
    const Matrix4& inv = s.modelviewInverse;
    for (int j = 0; j < 3; ++j) {
      normal[j] = n[0] * inv.at(0, j) + n[1] * inv.at(1, j) + n[2] * inv.at(2, j);
    }
    if (s.normalize) {
      const float length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] +
                                     normal[2] * normal[2]);
      if (length > 0.0f) {
        for (float& c : normal) c /= length;
      }
    } else if (s.rescaleNormal) {
      for (float& c : normal) c *= s.rescaleFactor;
    }
  }

  float* varyings = v.varyings;
  if (s.lightPerVertex) {
    LitVertexColors lit;
    lightVertex(ctx, eye, normal, lit);
    copy4Clamped(lit.front, varyings + varying::kPrimaryColor);
    copy4Clamped(lit.frontSecondary, varyings + varying::kSecondaryColor);
    if (s.twoSided) {
      copy4Clamped(lit.back, out.backColor);
      copy4Clamped(lit.backSecondary, out.backSecondary);
    }
  } else {
    // Unlit, or Phong: the current colour, clamped (spec 2.14.6); for Phong it is the input of
    // colour material in the per-fragment lighting.
    copy4Clamped(ctx.current.color, varyings + varying::kPrimaryColor);
    for (int i = 0; i < 4; ++i) varyings[varying::kSecondaryColor + i] = 0.0f;
    if (s.secondaryColor) {
      // The sum adds R, G and B only; the secondary alpha is 0 (spec 2.14.6).
      for (int i = 0; i < 3; ++i) {
        varyings[varying::kSecondaryColor + i] = clamp01(ctx.current.secondaryColor[i]);
      }
    }
  }

  if (s.fog) varyings[varying::kFogCoordinate] = fogCoordinate(ctx, eye, ctx.current.fogCoord);
  if (s.texturing)
    computeTexCoords(ctx, s.textureUnits, ctx.current.texCoord, object, eye, normal, varyings);
  if (s.eyeNormalVarying) {
    const float w = eye[3] != 0.0f ? eye[3] : 1.0f;
    for (int i = 0; i < 3; ++i) {
      varyings[varying::kEyePosition + i] = eye[i] / w;
      varyings[varying::kEyeNormal + i] = normal[i];
    }
  }

  for (int i = 0; i < raster::kMaxUserClipPlanes; ++i) {
    if (s.clipPlaneMask & (1u << i)) {
      const float* p = s.clipPlanes[i];
      v.userClipDistance[i] = p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] + p[3] * eye[3];
    } else {
      v.userClipDistance[i] = 0.0f;
    }
  }
  if (s.trace) traceVertex(ctx, s, *s.trace, object, eye, normal, out);
}

}  // namespace glass::gl
