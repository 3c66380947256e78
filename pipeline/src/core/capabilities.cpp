#include "core/capabilities.h"

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "fragment/fog_hooks.h"
#include "lighting/lighting_hooks.h"
#include "pixels/imaging_queries.h"
#include "texture/texture_hooks.h"

namespace glass::gl {

namespace {

// The flag of a capability the pipeline core owns, or nullptr.
bool* coreCapability(Context& ctx, GLenum cap) {
  TransformState& t = ctx.transform;
  RasterState& r = ctx.raster;
  FragmentState& f = ctx.fragment;
  switch (cap) {
    case GL_NORMALIZE: return &t.normalize;
    case GL_RESCALE_NORMAL: return &t.rescaleNormal;
    case GL_CULL_FACE: return &r.cullFace;
    case GL_LINE_STIPPLE: return &r.lineStipple;
    case GL_POLYGON_OFFSET_FILL: return &r.polygonOffsetFill;
    case GL_POLYGON_OFFSET_LINE: return &r.polygonOffsetLine;
    case GL_POLYGON_OFFSET_POINT: return &r.polygonOffsetPoint;
    case GL_POINT_SMOOTH: return &r.pointSmooth;
    case GL_LINE_SMOOTH: return &r.lineSmooth;
    case GL_POLYGON_SMOOTH: return &r.polygonSmooth;
    case GL_POLYGON_STIPPLE: return &r.polygonStipple;
    case GL_SCISSOR_TEST: return &f.scissorTest;
    case GL_ALPHA_TEST: return &f.alphaTest;
    case GL_STENCIL_TEST: return &f.stencilTest;
    case GL_DEPTH_TEST: return &f.depthTest;
    case GL_BLEND: return &f.blend;
    case GL_COLOR_LOGIC_OP: return &f.colorLogicOp;
    case GL_INDEX_LOGIC_OP: return &f.indexLogicOp;
    case GL_DITHER: return &f.dither;
    case GL_MULTISAMPLE: return &f.multisample;  // fragment/multisample.h: no sample buffers
    case GL_SAMPLE_ALPHA_TO_COVERAGE: return &f.sampleAlphaToCoverage;
    case GL_SAMPLE_ALPHA_TO_ONE: return &f.sampleAlphaToOne;
    case GL_SAMPLE_COVERAGE: return &f.sampleCoverage;
    default: return imagingCapability(ctx.imaging, cap);  // pixels/imaging_queries.h
  }
}

const ClientArray* clientArray(const Context& ctx, GLenum cap) {
  const ArrayState& a = ctx.arrays;
  switch (cap) {
    case GL_VERTEX_ARRAY: return &a.vertex;
    case GL_COLOR_ARRAY: return &a.color;
    case GL_NORMAL_ARRAY: return &a.normal;
    case GL_TEXTURE_COORD_ARRAY: return &a.texCoord[a.clientActiveUnit];
    case GL_EDGE_FLAG_ARRAY: return &a.edgeFlag;
    case GL_INDEX_ARRAY: return &a.index;
    case GL_FOG_COORDINATE_ARRAY: return &a.fogCoord;
    case GL_SECONDARY_COLOR_ARRAY: return &a.secondaryColor;
    default: return nullptr;
  }
}

bool isClipPlane(GLenum cap) {
  return cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + raster::kMaxUserClipPlanes;
}

}  // namespace

bool setCapability(Context& ctx, GLenum cap, bool enabled) {
  if (bool* flag = coreCapability(ctx, cap)) {
    *flag = enabled;
    return true;
  }
  if (isClipPlane(cap)) {
    const unsigned bit = 1u << (cap - GL_CLIP_PLANE0);
    ctx.transform.clipPlaneEnabled =
        enabled ? (ctx.transform.clipPlaneEnabled | bit) : (ctx.transform.clipPlaneEnabled & ~bit);
    return true;
  }
  return setLightingCapability(ctx, cap, enabled) || setFogCapability(ctx, cap, enabled) ||
         setTextureCapability(ctx, cap, enabled) || setEvaluatorCapability(ctx, cap, enabled);
}

bool getCapability(const Context& ctx, GLenum cap, bool& enabled) {
  // coreCapability only hands out a pointer; nothing is written through it here.
  if (const bool* flag = coreCapability(const_cast<Context&>(ctx), cap)) {
    enabled = *flag;
    return true;
  }
  if (isClipPlane(cap)) {
    enabled = (ctx.transform.clipPlaneEnabled >> (cap - GL_CLIP_PLANE0)) & 1u;
    return true;
  }
  if (const ClientArray* array = clientArray(ctx, cap)) {
    enabled = array->enabled;
    return true;
  }
  return getLightingCapability(ctx, cap, enabled) || getFogCapability(ctx, cap, enabled) ||
         getTextureCapability(ctx, cap, enabled) || getEvaluatorCapability(ctx, cap, enabled);
}

}  // namespace glass::gl
