// glPushAttrib, glPopAttrib, glPushClientAttrib and glPopClientAttrib (OpenGL 1.5
// specification, section 6.1.14 and the "attribute" column of tables 6.5-6.30).
//
// A push copies the state of every group its mask names into a new entry; a pop writes back the
// groups of the top entry and removes it. Pushing onto a full stack sets GL_STACK_OVERFLOW and
// popping an empty one GL_STACK_UNDERFLOW, changing nothing. glPushAttrib and glPopAttrib are
// compiled into display lists; the client versions are not (spec 5.4).
//
// GL_CURRENT_BIT includes the current raster position, GL_PIXEL_MODE_BIT the pixel transfer
// state and zoom (the pixel maps belong to no group, table 6.17) and the imaging subset's enables,
// scales, biases and convolution parameters (its tables and filters belong to no group), GL_ACCUM_BUFFER_BIT the
// accumulation buffer's clear value, GL_POLYGON_STIPPLE_BIT the stipple pattern.
#include "core/attrib_stack.h"

#include <cstring>

#include "core/capabilities.h"
#include "core/context.h"
#include "core/errors.h"
#include "core/state_value.h"
#include "fragment/buffer_selection.h"
#include "lighting/lighting_hooks.h"
#include "lists/command_recording.h"
#include "texture/texture_object.h"

namespace glass::gl {

namespace {

// Every capability GL_ENABLE_BIT saves (table 6.x "enable" attributes), where glass has it.
constexpr GLenum kEnableCapabilities[] = {
    GL_ALPHA_TEST, GL_AUTO_NORMAL, GL_BLEND, GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_CLIP_PLANE2,
    GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5, GL_COLOR_MATERIAL, GL_CULL_FACE,
    GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4,
    GL_LIGHT5, GL_LIGHT6, GL_LIGHT7, GL_LIGHTING, GL_LINE_SMOOTH, GL_LINE_STIPPLE,
    GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP, GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_NORMALIZE, GL_POINT_SMOOTH,
    GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE, GL_RESCALE_NORMAL, GL_SCISSOR_TEST, GL_STENCIL_TEST,
    GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
    GL_COLOR_SUM,
    // The imaging subset's (tables 6.18-6.22: also in GL_PIXEL_MODE_BIT).
    GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE,
    GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D, GL_HISTOGRAM, GL_MINMAX};
constexpr int kEnableCount = sizeof(kEnableCapabilities) / sizeof(kEnableCapabilities[0]);

// The texture enables of one unit, which GL_ENABLE_BIT saves for every unit (GL_TEXTURE_1D,
// GL_TEXTURE_2D, GL_TEXTURE_GEN_S/T/R/Q are per-unit state, spec 3.8.17 and table 6.19).
struct TextureUnitEnables {
  bool enabled1D, enabled2D, enabled3D, enabledCube;
  bool texGen[4];
};

// The texture state GL_TEXTURE_BIT saves for one unit: enables, bindings (by name), the bound
// objects' parameters, the environment and texture coordinate generation.
struct TextureUnitAttributes {
  TextureUnitEnables enables;
  GLuint bound1D, bound2D, bound3D, boundCube;
  SamplerParameters params1D, params2D, params3D, paramsCube;
  TextureEnvironment env;
  TexGenCoordinate texGen[4];
};

// GL_TEXTURE_BIT: every unit, the active unit and the bump-mapping parameters.
struct TextureAttributes {
  TextureUnitAttributes units[kTextureUnitCount];
  int activeUnit;
  BumpMapState bumpMap;
};

}  // namespace

struct AttribEntry {
  GLbitfield mask = 0;
  CurrentState current;
  RasterState raster;
  FragmentState fragment;
  LightingState lighting;
  FogState fog;
  HintState hints;
  EvaluatorAttributes evaluators;
  GLuint listBase = 0;
  // GL_TRANSFORM_BIT and GL_VIEWPORT_BIT: the parts of TransformState that are not matrices.
  GLenum matrixMode = GL_MODELVIEW;
  double clipPlanes[raster::kMaxUserClipPlanes][4] = {};
  unsigned clipPlaneEnabled = 0;
  bool normalize = false, rescaleNormal = false;
  Viewport viewport;
  double depthNear = 0.0, depthFar = 1.0;
  TextureAttributes texture{};
  RasterPositionState rasterPosition;  // GL_CURRENT_BIT
  PixelTransferState pixelTransfer;    // GL_PIXEL_MODE_BIT, without the maps
  ImagingPixelMode imagingMode;        // GL_PIXEL_MODE_BIT: the imaging subset's part
  float accumulationClear[4] = {};     // GL_ACCUM_BUFFER_BIT
  bool enableKnown[kEnableCount] = {};
  bool enabled[kEnableCount] = {};
  TextureUnitEnables textureEnables[kTextureUnitCount] = {};  // GL_ENABLE_BIT
};

struct ClientAttribEntry {
  GLbitfield mask = 0;
  PixelStoreState pixelStore;
  ArrayState arrays;
};

namespace {

TextureObject* boundObject(TextureState& t, GLenum target, GLuint name) {
  TextureObject* fallback = target == GL_TEXTURE_1D   ? &t.default1D
                            : target == GL_TEXTURE_2D ? &t.default2D
                            : target == GL_TEXTURE_3D ? &t.default3D
                                                      : &t.defaultCube;
  if (name == 0) return fallback;
  const std::shared_ptr<TextureObject> found = t.names->find(name);
  // A texture deleted since the push is no longer there: the binding falls back to the default.
  if (!found || found->target != target) return fallback;
  return found.get();
}

TextureUnitEnables saveTextureEnables(const TextureUnit& u) {
  TextureUnitEnables e{};
  e.enabled1D = u.enabled1D;
  e.enabled2D = u.enabled2D;
  e.enabled3D = u.enabled3D;
  e.enabledCube = u.enabledCube;
  for (int i = 0; i < 4; ++i) e.texGen[i] = u.texGen[i].enabled;
  return e;
}

void restoreTextureEnables(TextureUnit& u, const TextureUnitEnables& e) {
  u.enabled1D = e.enabled1D;
  u.enabled2D = e.enabled2D;
  u.enabled3D = e.enabled3D;
  u.enabledCube = e.enabledCube;
  for (int i = 0; i < 4; ++i) u.texGen[i].enabled = e.texGen[i];
}

TextureAttributes saveTexture(const TextureState& t) {
  TextureAttributes a{};
  for (int n = 0; n < kTextureUnitCount; ++n) {
    const TextureUnit& u = t.units[n];
    TextureUnitAttributes& s = a.units[n];
    s.enables = saveTextureEnables(u);
    s.bound1D = u.bound1D->name;
    s.bound2D = u.bound2D->name;
    s.params1D = u.bound1D->params;
    s.params2D = u.bound2D->params;
    s.bound3D = u.bound3D->name;
    s.params3D = u.bound3D->params;
    s.boundCube = u.boundCube->name;
    s.paramsCube = u.boundCube->params;
    s.env = u.env;
    for (int i = 0; i < 4; ++i) s.texGen[i] = u.texGen[i];
  }
  a.activeUnit = t.activeUnit;
  a.bumpMap = t.bumpMap;
  return a;
}

void restoreTexture(TextureState& t, const TextureAttributes& a) {
  for (int n = 0; n < kTextureUnitCount; ++n) {
    TextureUnit& u = t.units[n];
    const TextureUnitAttributes& s = a.units[n];
    for (int i = 0; i < 4; ++i) u.texGen[i] = s.texGen[i];
    restoreTextureEnables(u, s.enables);
    u.bound1D = boundObject(t, GL_TEXTURE_1D, s.bound1D);
    u.bound2D = boundObject(t, GL_TEXTURE_2D, s.bound2D);
    if (u.bound1D->name == s.bound1D) {
      u.bound1D->params = s.params1D;
      u.bound1D->updateCompleteness();
    }
    if (u.bound2D->name == s.bound2D) {
      u.bound2D->params = s.params2D;
      u.bound2D->updateCompleteness();
    }
    u.bound3D = boundObject(t, GL_TEXTURE_3D, s.bound3D);
    if (u.bound3D->name == s.bound3D) {
      u.bound3D->params = s.params3D;
      u.bound3D->updateCompleteness();
    }
    u.boundCube = boundObject(t, GL_TEXTURE_CUBE_MAP, s.boundCube);
    if (u.boundCube->name == s.boundCube) {
      u.boundCube->params = s.paramsCube;
      u.boundCube->updateCompleteness();
    }
    u.env = s.env;
  }
  t.activeUnit = a.activeUnit;
  t.bumpMap = a.bumpMap;
  t.holdBindings();
}

std::shared_ptr<const AttribEntry> saveAttributes(const Context& ctx, GLbitfield mask) {
  auto e = std::make_shared<AttribEntry>();
  e->mask = mask;
  // Whole stage states are small enough to copy as they are; pop restores only the groups asked.
  if (mask & GL_CURRENT_BIT) {
    e->current = ctx.current;
    e->rasterPosition = ctx.rasterPosition;
  }
  if (mask & (GL_POINT_BIT | GL_LINE_BIT | GL_POLYGON_BIT | GL_POLYGON_STIPPLE_BIT | GL_LIGHTING_BIT)) {
    e->raster = ctx.raster;
  }
  if (mask & GL_PIXEL_MODE_BIT) {
    e->pixelTransfer = ctx.pixelTransfer;
    e->pixelTransfer.maps = {};
    e->imagingMode = ctx.imaging.mode;
  }
  if (mask & GL_ACCUM_BUFFER_BIT) {
    std::memcpy(e->accumulationClear, ctx.accumulation.clearValue, sizeof e->accumulationClear);
  }
  if (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT | GL_SCISSOR_BIT |
              GL_MULTISAMPLE_BIT)) {
    e->fragment = ctx.fragment;
  }
  if (mask & GL_LIGHTING_BIT) e->lighting = ctx.lighting;
  if (mask & GL_FOG_BIT) e->fog = ctx.fog;
  if (mask & GL_HINT_BIT) e->hints = ctx.hints;
  if (mask & GL_EVAL_BIT) e->evaluators = ctx.evaluators.attributes;
  if (mask & GL_LIST_BIT) e->listBase = ctx.lists.listBase;
  const TransformState& t = ctx.transform;
  if (mask & GL_TRANSFORM_BIT) {
    e->matrixMode = t.matrixMode;
    std::memcpy(e->clipPlanes, t.clipPlanes, sizeof e->clipPlanes);
    e->clipPlaneEnabled = t.clipPlaneEnabled;
    e->normalize = t.normalize;
    e->rescaleNormal = t.rescaleNormal;
  }
  if (mask & GL_VIEWPORT_BIT) {
    e->viewport = t.viewport;
    e->depthNear = t.depthNear;
    e->depthFar = t.depthFar;
  }
  if (mask & GL_TEXTURE_BIT) e->texture = saveTexture(ctx.texture);
  if (mask & GL_ENABLE_BIT) {
    for (int i = 0; i < kEnableCount; ++i) {
      bool on = false;
      e->enableKnown[i] = getCapability(ctx, kEnableCapabilities[i], on);
      e->enabled[i] = on;
    }
    for (int n = 0; n < kTextureUnitCount; ++n)
      e->textureEnables[n] = saveTextureEnables(ctx.texture.units[n]);
  }
  return e;
}

void restoreAttributes(Context& ctx, const AttribEntry& e) {
  const GLbitfield mask = e.mask;
  // Enables first: the groups restored after them (lighting, fog, ...) carry their own enables
  // too, and the values they saved are the same.
  if (mask & GL_ENABLE_BIT) {
    for (int i = 0; i < kEnableCount; ++i) {
      if (e.enableKnown[i]) setCapability(ctx, kEnableCapabilities[i], e.enabled[i]);
    }
    for (int n = 0; n < kTextureUnitCount; ++n)
      restoreTextureEnables(ctx.texture.units[n], e.textureEnables[n]);
  }
  if (mask & GL_CURRENT_BIT) {
    ctx.current = e.current;
    ctx.rasterPosition = e.rasterPosition;
  }
  if (mask & GL_PIXEL_MODE_BIT) {
    auto maps = std::move(ctx.pixelTransfer.maps);
    ctx.pixelTransfer = e.pixelTransfer;
    ctx.pixelTransfer.maps = std::move(maps);
    ctx.imaging.mode = e.imagingMode;
  }
  if (mask & GL_ACCUM_BUFFER_BIT) {
    std::memcpy(ctx.accumulation.clearValue, e.accumulationClear, sizeof e.accumulationClear);
  }
  RasterState& r = ctx.raster;
  if (mask & GL_POLYGON_STIPPLE_BIT) r.polygonStipplePattern = e.raster.polygonStipplePattern;
  if (mask & GL_POINT_BIT) {
    r.pointSize = e.raster.pointSize;
    r.pointSmooth = e.raster.pointSmooth;
    r.pointSizeMin = e.raster.pointSizeMin;
    r.pointSizeMax = e.raster.pointSizeMax;
    r.pointFadeThreshold = e.raster.pointFadeThreshold;
    std::memcpy(r.pointDistanceAttenuation, e.raster.pointDistanceAttenuation,
                sizeof r.pointDistanceAttenuation);
  }
  if (mask & GL_LINE_BIT) {
    r.lineWidth = e.raster.lineWidth;
    r.lineSmooth = e.raster.lineSmooth;
    r.lineStipple = e.raster.lineStipple;
    r.lineStippleFactor = e.raster.lineStippleFactor;
    r.lineStipplePattern = e.raster.lineStipplePattern;
  }
  if (mask & GL_POLYGON_BIT) {
    r.cullFace = e.raster.cullFace;
    r.cullFaceMode = e.raster.cullFaceMode;
    r.frontFace = e.raster.frontFace;
    r.polygonModeFront = e.raster.polygonModeFront;
    r.polygonModeBack = e.raster.polygonModeBack;
    r.polygonSmooth = e.raster.polygonSmooth;
    r.polygonStipple = e.raster.polygonStipple;
    r.polygonOffsetFactor = e.raster.polygonOffsetFactor;
    r.polygonOffsetUnits = e.raster.polygonOffsetUnits;
    r.polygonOffsetFill = e.raster.polygonOffsetFill;
    r.polygonOffsetLine = e.raster.polygonOffsetLine;
    r.polygonOffsetPoint = e.raster.polygonOffsetPoint;
  }
  if (mask & GL_LIGHTING_BIT) {
    ctx.lighting = e.lighting;
    r.shadeModel = e.raster.shadeModel;
  }
  // While colour material is on, the parameters it names track the current colour (spec
  // 2.13.3), whichever of the material, the colour and the enable came back: popping
  // GL_LIGHTING_BIT alone does not bring back a material that differs from the current colour
  // (Mesa's pipeline reads the current colour for them in that case too).
  if (mask & (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT)) onCurrentColorChanged(ctx);
  if (mask & GL_FOG_BIT) ctx.fog = e.fog;
  FragmentState& f = ctx.fragment;
  const FragmentState& s = e.fragment;
  if (mask & GL_DEPTH_BUFFER_BIT) {
    f.depthTest = s.depthTest;
    f.depthFunc = s.depthFunc;
    f.depthMask = s.depthMask;
    f.clearDepth = s.clearDepth;
  }
  if (mask & GL_STENCIL_BUFFER_BIT) {
    f.stencilTest = s.stencilTest;
    f.stencilFunc = s.stencilFunc;
    f.stencilRef = s.stencilRef;
    f.stencilValueMask = s.stencilValueMask;
    f.stencilFail = s.stencilFail;
    f.stencilDepthFail = s.stencilDepthFail;
    f.stencilDepthPass = s.stencilDepthPass;
    f.stencilWriteMask = s.stencilWriteMask;
    f.clearStencil = s.clearStencil;
  }
  if (mask & GL_COLOR_BUFFER_BIT) {
    f.alphaTest = s.alphaTest;
    f.alphaFunc = s.alphaFunc;
    f.alphaRef = s.alphaRef;
    f.blend = s.blend;
    f.blendSrcRGB = s.blendSrcRGB;
    f.blendDstRGB = s.blendDstRGB;
    f.blendSrcAlpha = s.blendSrcAlpha;
    f.blendDstAlpha = s.blendDstAlpha;
    f.blendEquation = s.blendEquation;
    std::memcpy(f.blendColor, s.blendColor, sizeof f.blendColor);
    f.dither = s.dither;
    f.colorLogicOp = s.colorLogicOp;
    f.indexLogicOp = s.indexLogicOp;
    f.logicOp = s.logicOp;
    std::memcpy(f.colorMask, s.colorMask, sizeof f.colorMask);
    std::memcpy(f.clearColor, s.clearColor, sizeof f.clearColor);
    f.clearIndex = s.clearIndex;
    f.indexMask = s.indexMask;
    f.drawBuffer = s.drawBuffer;
  }
  if (mask & GL_SCISSOR_BIT) {
    f.scissorTest = s.scissorTest;
    f.scissor = s.scissor;
  }
  if (mask & GL_MULTISAMPLE_BIT) {
    f.multisample = s.multisample;
    f.sampleAlphaToCoverage = s.sampleAlphaToCoverage;
    f.sampleAlphaToOne = s.sampleAlphaToOne;
    f.sampleCoverage = s.sampleCoverage;
    f.sampleCoverageValue = s.sampleCoverageValue;
    f.sampleCoverageInvert = s.sampleCoverageInvert;
  }
  TransformState& t = ctx.transform;
  if (mask & GL_TRANSFORM_BIT) {
    t.matrixMode = e.matrixMode;
    std::memcpy(t.clipPlanes, e.clipPlanes, sizeof t.clipPlanes);
    t.clipPlaneEnabled = e.clipPlaneEnabled;
    t.normalize = e.normalize;
    t.rescaleNormal = e.rescaleNormal;
  }
  if (mask & GL_VIEWPORT_BIT) {
    t.viewport = e.viewport;
    t.depthNear = e.depthNear;
    t.depthFar = e.depthFar;
  }
  if (mask & GL_HINT_BIT) ctx.hints = e.hints;
  if (mask & GL_EVAL_BIT) ctx.evaluators.attributes = e.evaluators;
  if (mask & GL_LIST_BIT) ctx.lists.listBase = e.listBase;
  if (mask & GL_TEXTURE_BIT) restoreTexture(ctx.texture, e.texture);
}

void pushAttrib(Context& ctx, GLbitfield mask) {
  if (rejectInsideBeginEnd(ctx)) return;
  auto& stack = ctx.attribStack.server;
  if (static_cast<int>(stack.size()) >= kMaxAttribStackDepth) {
    recordError(ctx, GL_STACK_OVERFLOW);
    return;
  }
  stack.push_back(saveAttributes(ctx, mask));
}

void popAttrib(Context& ctx) {
  if (rejectInsideBeginEnd(ctx)) return;
  auto& stack = ctx.attribStack.server;
  if (stack.empty()) {
    recordError(ctx, GL_STACK_UNDERFLOW);
    return;
  }
  const std::shared_ptr<const AttribEntry> top = stack.back();
  stack.pop_back();
  restoreAttributes(ctx, *top);
  selectDrawBuffer(ctx);  // the draw buffer restored may be another colour buffer
}

void pushClientAttrib(Context& ctx, GLbitfield mask) {
  if (rejectInsideBeginEnd(ctx)) return;
  auto& stack = ctx.attribStack.client;
  if (static_cast<int>(stack.size()) >= kMaxClientAttribStackDepth) {
    recordError(ctx, GL_STACK_OVERFLOW);
    return;
  }
  auto e = std::make_shared<ClientAttribEntry>();
  e->mask = mask;
  if (mask & GL_CLIENT_PIXEL_STORE_BIT) e->pixelStore = ctx.pixelStore;
  if (mask & GL_CLIENT_VERTEX_ARRAY_BIT) e->arrays = ctx.arrays;
  stack.push_back(std::move(e));
}

void popClientAttrib(Context& ctx) {
  if (rejectInsideBeginEnd(ctx)) return;
  auto& stack = ctx.attribStack.client;
  if (stack.empty()) {
    recordError(ctx, GL_STACK_UNDERFLOW);
    return;
  }
  const std::shared_ptr<const ClientAttribEntry> top = stack.back();
  stack.pop_back();
  if (top->mask & GL_CLIENT_PIXEL_STORE_BIT) ctx.pixelStore = top->pixelStore;
  if (top->mask & GL_CLIENT_VERTEX_ARRAY_BIT) ctx.arrays = top->arrays;
}

}  // namespace

bool queryAttribStackState(const Context& ctx, GLenum pname, StateValue& value) {
  switch (pname) {
    case GL_ATTRIB_STACK_DEPTH:
      value.setIntegers({double(ctx.attribStack.server.size())});
      return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: value.setIntegers({double(kMaxAttribStackDepth)}); return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH:
      value.setIntegers({double(ctx.attribStack.client.size())});
      return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH:
      value.setIntegers({double(kMaxClientAttribStackDepth)});
      return true;
    default: return false;
  }
}

}  // namespace glass::gl

using glass::gl::Context;

extern "C" {

void glPushAttrib(GLbitfield mask) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::pushAttrib(ctx, mask); });
}

void glPopAttrib(void) {
  glass::gl::compileOrExecute([](Context& ctx) { glass::gl::popAttrib(ctx); });
}

void glPushClientAttrib(GLbitfield mask) {
  glass::gl::executeNow([=](Context& ctx) { glass::gl::pushClientAttrib(ctx, mask); });
}

void glPopClientAttrib(void) {
  glass::gl::executeNow([](Context& ctx) { glass::gl::popClientAttrib(ctx); });
}

}  // extern "C"
