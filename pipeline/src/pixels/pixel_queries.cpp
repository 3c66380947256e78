#include "pixels/pixel_queries.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryPixelState(const Context& ctx, GLenum pname, StateValue& v) {
  const RasterPositionState& r = ctx.rasterPosition;
  const PixelTransferState& t = ctx.pixelTransfer;
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname < GL_PIXEL_MAP_I_TO_I_SIZE + kPixelMapCount) {
    v.setIntegers({static_cast<double>(t.maps[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size())});
    return true;
  }
  switch (pname) {
    case GL_CURRENT_RASTER_POSITION: v.setFloats(r.window, 4); return true;
    case GL_CURRENT_RASTER_POSITION_VALID: v.setBooleans({r.valid}); return true;
    case GL_CURRENT_RASTER_DISTANCE: v.setFloats({r.distance}); return true;
    case GL_CURRENT_RASTER_COLOR: v.setColors(r.color, 4); return true;
    case GL_CURRENT_RASTER_INDEX: v.setFloats({r.index}); return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS:
      v.setFloats(r.texCoord[ctx.texture.activeUnit], 4);
      return true;

    case GL_MAP_COLOR: v.setBooleans({t.mapColor}); return true;
    case GL_MAP_STENCIL: v.setBooleans({t.mapStencil}); return true;
    case GL_INDEX_SHIFT: v.setIntegers({double(t.indexShift)}); return true;
    case GL_INDEX_OFFSET: v.setIntegers({double(t.indexOffset)}); return true;
    case GL_RED_SCALE: v.setFloats({t.scale[0]}); return true;
    case GL_GREEN_SCALE: v.setFloats({t.scale[1]}); return true;
    case GL_BLUE_SCALE: v.setFloats({t.scale[2]}); return true;
    case GL_ALPHA_SCALE: v.setFloats({t.scale[3]}); return true;
    case GL_RED_BIAS: v.setFloats({t.bias[0]}); return true;
    case GL_GREEN_BIAS: v.setFloats({t.bias[1]}); return true;
    case GL_BLUE_BIAS: v.setFloats({t.bias[2]}); return true;
    case GL_ALPHA_BIAS: v.setFloats({t.bias[3]}); return true;
    case GL_DEPTH_SCALE: v.setFloats({t.depthScale}); return true;
    case GL_DEPTH_BIAS: v.setFloats({t.depthBias}); return true;
    case GL_ZOOM_X: v.setFloats({t.zoomX}); return true;
    case GL_ZOOM_Y: v.setFloats({t.zoomY}); return true;
    case GL_MAX_PIXEL_MAP_TABLE: v.setIntegers({kMaxPixelMapTable}); return true;
    default: return false;
  }
}

}  // namespace glass::gl
