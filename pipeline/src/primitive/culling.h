// Face culling (spec 3.5.1): with GL_CULL_FACE enabled, polygons whose facing glCullFace names
// are discarded (GL_FRONT_AND_BACK discards every polygon; points and lines are never culled).
#pragma once

#include <GL/gl.h>

#include "primitive/raster_state.h"

namespace glass::gl {

inline bool isCulled(const RasterState& state, bool frontFacing) {
  if (!state.cullFace) return false;
  switch (state.cullFaceMode) {
    case GL_FRONT: return frontFacing;
    case GL_BACK: return !frontFacing;
    default: return true;  // GL_FRONT_AND_BACK
  }
}

}  // namespace glass::gl
