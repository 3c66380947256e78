#include "core/state_query.h"

#include "core/attrib_stack.h"

#include "accum/accumulation.h"
#include "core/capabilities.h"
#include "core/color_index.h"
#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "fragment/buffer_selection.h"
#include "fragment/fog_hooks.h"
#include "fragment/multisample.h"
#include "lighting/lighting_hooks.h"
#include "pixels/imaging_queries.h"
#include "pixels/pixel_queries.h"
#include "primitive/point_parameters.h"
#include "select/render_mode_query.h"
#include "texture/compressed_textures.h"
#include "texture/texture_hooks.h"
#include "texture/texture_units.h"
#include "vertex/secondary_attributes.h"

namespace glass::gl {

namespace {

void setMatrix(StateValue& value, const Matrix4& m) { value.setFloats(m.m, 16); }

void setTransposedMatrix(StateValue& value, const Matrix4& m) {
  float t[16];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) t[r * 4 + c] = m.at(r, c);
  }
  value.setFloats(t, 16);
}

bool queryArrayState(const ClientArray& a, GLenum pname, GLenum sizeName, GLenum typeName,
                     GLenum strideName, StateValue& value) {
  if (pname == sizeName && sizeName != 0) {
    value.setIntegers({static_cast<double>(a.size)});
  } else if (pname == typeName && typeName != 0) {
    value.setIntegers({static_cast<double>(a.type)});
  } else if (pname == strideName) {
    value.setIntegers({static_cast<double>(a.stride)});
  } else {
    return false;
  }
  return true;
}

bool queryPixelStore(const PixelPacking& p, GLenum pname, GLenum base, GLenum imagesBase, StateValue& value) {
  // The 3D layout (OpenGL 1.2): GL_PACK_SKIP_IMAGES / GL_UNPACK_SKIP_IMAGES, then the image height.
  if (pname == imagesBase) {
    value.setIntegers({double(p.skipImages)});
    return true;
  }
  if (pname == imagesBase + 1) {
    value.setIntegers({double(p.imageHeight)});
    return true;
  }
  // GL_PACK_* and GL_UNPACK_* names are the same offsets from GL_PACK_SWAP_BYTES / GL_UNPACK_....
  switch (pname - base) {
    case GL_PACK_SWAP_BYTES - GL_PACK_SWAP_BYTES: value.setBooleans({p.swapBytes}); return true;
    case GL_PACK_LSB_FIRST - GL_PACK_SWAP_BYTES: value.setBooleans({p.lsbFirst}); return true;
    case GL_PACK_ROW_LENGTH - GL_PACK_SWAP_BYTES: value.setIntegers({double(p.rowLength)}); return true;
    case GL_PACK_SKIP_ROWS - GL_PACK_SWAP_BYTES: value.setIntegers({double(p.skipRows)}); return true;
    case GL_PACK_SKIP_PIXELS - GL_PACK_SWAP_BYTES: value.setIntegers({double(p.skipPixels)}); return true;
    case GL_PACK_ALIGNMENT - GL_PACK_SWAP_BYTES: value.setIntegers({double(p.alignment)}); return true;
    default: return false;
  }
}

bool queryCoreState(const Context& ctx, GLenum pname, StateValue& v) {
  const TransformState& t = ctx.transform;
  const CurrentState& cur = ctx.current;
  const RasterState& r = ctx.raster;
  const FragmentState& f = ctx.fragment;
  const DisplayListState& lists = ctx.lists;
  const ArrayState& arrays = ctx.arrays;
  const PixelStoreState& pixels = ctx.pixelStore;
  // The texture matrix and current coordinates of the active unit (spec 2.7, 2.11.2).
  const MatrixStack& textureStack = t.texture[ctx.texture.activeUnit];

  switch (pname) {
    // Transformation (table 6.7, 6.8)
    case GL_MATRIX_MODE: v.setIntegers({double(t.matrixMode)}); return true;
    case GL_MODELVIEW_MATRIX: setMatrix(v, t.modelview.top()); return true;
    case GL_PROJECTION_MATRIX: setMatrix(v, t.projection.top()); return true;
    case GL_TEXTURE_MATRIX: setMatrix(v, textureStack.top()); return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX: setTransposedMatrix(v, t.modelview.top()); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: setTransposedMatrix(v, t.projection.top()); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX: setTransposedMatrix(v, textureStack.top()); return true;
    // The imaging subset's colour matrix stack (glMatrixMode(GL_COLOR), spec 3.6.3).
    case GL_COLOR_MATRIX: setMatrix(v, ctx.imaging.colorMatrix.top()); return true;
    case GL_TRANSPOSE_COLOR_MATRIX: setTransposedMatrix(v, ctx.imaging.colorMatrix.top()); return true;
    case GL_COLOR_MATRIX_STACK_DEPTH: v.setIntegers({double(ctx.imaging.colorMatrix.depth())}); return true;
    case GL_MAX_COLOR_MATRIX_STACK_DEPTH: v.setIntegers({double(kColorMatrixStackDepth)}); return true;
    case GL_MODELVIEW_STACK_DEPTH: v.setIntegers({double(t.modelview.depth())}); return true;
    case GL_PROJECTION_STACK_DEPTH: v.setIntegers({double(t.projection.depth())}); return true;
    case GL_TEXTURE_STACK_DEPTH: v.setIntegers({double(textureStack.depth())}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: v.setIntegers({double(t.modelview.maxDepth())}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: v.setIntegers({double(t.projection.maxDepth())}); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: v.setIntegers({double(textureStack.maxDepth())}); return true;
    case GL_VIEWPORT:
      v.setIntegers({double(t.viewport.x), double(t.viewport.y), double(t.viewport.width),
                     double(t.viewport.height)});
      return true;
    case GL_MAX_VIEWPORT_DIMS: v.setIntegers({kMaxViewportSize, kMaxViewportSize}); return true;
    case GL_DEPTH_RANGE: v.setColors({t.depthNear, t.depthFar}); return true;
    case GL_MAX_CLIP_PLANES: v.setIntegers({raster::kMaxUserClipPlanes}); return true;

    // Current values (table 6.5)
    case GL_CURRENT_COLOR: v.setColors(cur.color, 4); return true;
    case GL_CURRENT_NORMAL: v.setColors(cur.normal, 3); return true;
    case GL_CURRENT_TEXTURE_COORDS:
      v.setFloats(cur.texCoord[ctx.texture.activeUnit], 4);
      return true;
    case GL_EDGE_FLAG: v.setBooleans({cur.edgeFlag}); return true;

    // Rasterization (tables 6.12, 6.13)
    case GL_POINT_SIZE: v.setFloats({r.pointSize}); return true;
    case GL_POINT_SIZE_RANGE:
    case GL_ALIASED_POINT_SIZE_RANGE: v.setFloats({1.0, kMaxPointSize}); return true;
    // Smooth points and lines take their size unrounded (smooth_coverage.h: the point's radius
    // is size / 2 above size 2, the line's half width w / 2 + 1/2), so sizes 0.1 apart draw
    // differently (tests/unit/implementation_limits_test.cpp); Mesa reports 0.1 too.
    case GL_POINT_SIZE_GRANULARITY: v.setFloats({0.1}); return true;
    case GL_LINE_WIDTH: v.setFloats({r.lineWidth}); return true;
    case GL_LINE_WIDTH_RANGE:
    case GL_ALIASED_LINE_WIDTH_RANGE: v.setFloats({1.0, kMaxLineWidth}); return true;
    case GL_LINE_WIDTH_GRANULARITY: v.setFloats({0.1}); return true;
    case GL_LINE_STIPPLE_PATTERN: v.setIntegers({double(r.lineStipplePattern)}); return true;
    case GL_LINE_STIPPLE_REPEAT: v.setIntegers({double(r.lineStippleFactor)}); return true;
    case GL_SHADE_MODEL: v.setIntegers({double(r.shadeModel)}); return true;
    case GL_POLYGON_MODE:
      v.setIntegers({double(r.polygonModeFront), double(r.polygonModeBack)});
      return true;
    case GL_CULL_FACE_MODE: v.setIntegers({double(r.cullFaceMode)}); return true;
    case GL_FRONT_FACE: v.setIntegers({double(r.frontFace)}); return true;
    case GL_POLYGON_OFFSET_FACTOR: v.setFloats({r.polygonOffsetFactor}); return true;
    case GL_POLYGON_OFFSET_UNITS: v.setFloats({r.polygonOffsetUnits}); return true;

    // Fragment operations and framebuffer control (tables 6.19-6.21)
    case GL_SCISSOR_BOX:
      v.setIntegers({double(f.scissor.x), double(f.scissor.y), double(f.scissor.width),
                     double(f.scissor.height)});
      return true;
    case GL_ALPHA_TEST_FUNC: v.setIntegers({double(f.alphaFunc)}); return true;
    case GL_ALPHA_TEST_REF: v.setColors({f.alphaRef}); return true;
    case GL_STENCIL_FUNC: v.setIntegers({double(f.stencilFunc)}); return true;
    case GL_STENCIL_REF: v.setIntegers({double(f.stencilRef)}); return true;
    // The masks as the 8-bit stencil buffer sees them (Mesa reports them so too).
    case GL_STENCIL_VALUE_MASK: v.setIntegers({double(f.stencilValueMask & 0xFFu)}); return true;
    case GL_STENCIL_FAIL: v.setIntegers({double(f.stencilFail)}); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: v.setIntegers({double(f.stencilDepthFail)}); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: v.setIntegers({double(f.stencilDepthPass)}); return true;
    case GL_STENCIL_WRITEMASK: v.setIntegers({double(f.stencilWriteMask & 0xFFu)}); return true;
    case GL_DEPTH_FUNC: v.setIntegers({double(f.depthFunc)}); return true;
    case GL_DEPTH_WRITEMASK: v.setBooleans({f.depthMask}); return true;
    case GL_BLEND_SRC:
    case GL_BLEND_SRC_RGB: v.setIntegers({double(f.blendSrcRGB)}); return true;
    case GL_BLEND_DST:
    case GL_BLEND_DST_RGB: v.setIntegers({double(f.blendDstRGB)}); return true;
    case GL_BLEND_SRC_ALPHA: v.setIntegers({double(f.blendSrcAlpha)}); return true;
    case GL_BLEND_DST_ALPHA: v.setIntegers({double(f.blendDstAlpha)}); return true;
    case GL_BLEND_EQUATION: v.setIntegers({double(f.blendEquation)}); return true;
    case GL_BLEND_COLOR: v.setColors(f.blendColor, 4); return true;
    case GL_LOGIC_OP_MODE: v.setIntegers({double(f.logicOp)}); return true;
    case GL_COLOR_WRITEMASK:
      v.setBooleans({f.colorMask[0], f.colorMask[1], f.colorMask[2], f.colorMask[3]});
      return true;
    case GL_COLOR_CLEAR_VALUE: v.setColors(f.clearColor, 4); return true;
    case GL_DEPTH_CLEAR_VALUE: v.setColors({f.clearDepth}); return true;
    case GL_STENCIL_CLEAR_VALUE: v.setIntegers({double(f.clearStencil)}); return true;

    // The framebuffer (table 6.33 and 6.34)
    case GL_ALPHA_BITS: v.setIntegers({ctx.buffers.colorAlpha ? 8.0 : 0.0}); return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS:
    case GL_SUBPIXEL_BITS:
      v.setIntegers({8});
      return true;
    case GL_STENCIL_BITS: v.setIntegers({ctx.buffers.stencil ? 8.0 : 0.0}); return true;
    case GL_DEPTH_BITS: v.setIntegers({ctx.buffers.depth ? 24.0 : 0.0}); return true;
    case GL_INDEX_BITS: case GL_AUX_BUFFERS:
      v.setIntegers({0});
      return true;
    case GL_RGBA_MODE: v.setBooleans({true}); return true;
    case GL_INDEX_MODE: case GL_STEREO: v.setBooleans({false}); return true;
    case GL_DOUBLEBUFFER: v.setBooleans({isDoubleBuffered(ctx)}); return true;
    case GL_DRAW_BUFFER: v.setIntegers({double(f.drawBuffer)}); return true;
    case GL_READ_BUFFER: v.setIntegers({double(ctx.pixelTransfer.readBuffer)}); return true;

    // Display lists (table 6.32, 6.33)
    case GL_LIST_BASE: v.setIntegers({double(lists.listBase)}); return true;
    case GL_LIST_INDEX: v.setIntegers({double(lists.compilingName)}); return true;
    case GL_LIST_MODE:
      v.setIntegers({lists.isCompiling() ? double(lists.compileMode) : 0.0});
      return true;
    case GL_MAX_LIST_NESTING: v.setIntegers({kMaxListNesting}); return true;

    // Hints (table 6.31)
    case GL_PERSPECTIVE_CORRECTION_HINT: v.setIntegers({double(ctx.hints.perspectiveCorrection)}); return true;
    case GL_POINT_SMOOTH_HINT: v.setIntegers({double(ctx.hints.pointSmooth)}); return true;
    case GL_LINE_SMOOTH_HINT: v.setIntegers({double(ctx.hints.lineSmooth)}); return true;
    case GL_POLYGON_SMOOTH_HINT: v.setIntegers({double(ctx.hints.polygonSmooth)}); return true;
    case GL_FOG_HINT: v.setIntegers({double(ctx.hints.fog)}); return true;
    case GL_GENERATE_MIPMAP_HINT: v.setIntegers({double(ctx.hints.generateMipmap)}); return true;
    case GL_TEXTURE_COMPRESSION_HINT: v.setIntegers({double(ctx.hints.textureCompression)}); return true;
    case GL_PHONG_HINT_WIN: v.setIntegers({double(ctx.hints.phong)}); return true;

    case GL_MAX_ELEMENTS_VERTICES: case GL_MAX_ELEMENTS_INDICES: v.setIntegers({1 << 20}); return true;
    default: break;
  }

  return queryArrayState(arrays.vertex, pname, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE,
                         GL_VERTEX_ARRAY_STRIDE, v) ||
         queryArrayState(arrays.color, pname, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE,
                         GL_COLOR_ARRAY_STRIDE, v) ||
         queryArrayState(arrays.normal, pname, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, v) ||
         queryArrayState(arrays.texCoord[arrays.clientActiveUnit], pname,
                         GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
                         GL_TEXTURE_COORD_ARRAY_STRIDE, v) ||
         queryArrayState(arrays.edgeFlag, pname, 0, 0, GL_EDGE_FLAG_ARRAY_STRIDE, v) ||
         queryPixelStore(pixels.pack, pname, GL_PACK_SWAP_BYTES, GL_PACK_SKIP_IMAGES, v) ||
         queryPixelStore(pixels.unpack, pname, GL_UNPACK_SWAP_BYTES, GL_UNPACK_SKIP_IMAGES, v);
}

}  // namespace

bool queryState(const Context& ctx, GLenum pname, StateValue& value) {
  if (queryCoreState(ctx, pname, value) || queryAttribStackState(ctx, pname, value) ||
      queryLightingState(ctx, pname, value) ||
      queryFogState(ctx, pname, value) || queryTextureState(ctx, pname, value) ||
      queryEvaluatorState(ctx, pname, value) || queryPixelState(ctx, pname, value) ||
      queryImagingState(ctx, pname, value) ||
      queryAccumulationState(ctx, pname, value) || queryRenderModeState(ctx, pname, value) ||
      queryColorIndexState(ctx, pname, value) || queryMultisampleState(ctx, pname, value) ||
      queryTextureUnitState(ctx, pname, value) || queryCompressedTextureState(ctx, pname, value) ||
      queryPointParameterState(ctx, pname, value) ||
      querySecondaryAttributeState(ctx, pname, value)) {
    return true;
  }
  bool enabled = false;
  if (getCapability(ctx, pname, enabled)) {
    value.setBooleans({enabled});
    return true;
  }
  return false;
}

}  // namespace glass::gl
