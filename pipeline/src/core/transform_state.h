// Transformation state (OpenGL 1.5 spec, sections 2.11 and 2.12; table 6.7 and 6.8): the matrix
// stacks, the viewport and depth range, the user clip planes, and normal processing.
#pragma once

#include <GL/gl.h>

#include "core/matrix_stack.h"
#include "glass/raster/vertex.h"
#include "texture/texture_units.h"

namespace glass::gl {

// Stack depths as in Mesa: the specification asks for at least 32, 2 and 2.
inline constexpr int kModelviewStackDepth = 32;
inline constexpr int kProjectionStackDepth = 32;
inline constexpr int kTextureStackDepth = 10;
// GL_MAX_VIEWPORT_DIMS, and the largest context glassCreateContext accepts.
inline constexpr int kMaxViewportSize = 16384;

struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};

struct TransformState {
  GLenum matrixMode = GL_MODELVIEW;
  MatrixStack modelview{kModelviewStackDepth};
  MatrixStack projection{kProjectionStackDepth};
  // One texture matrix stack per texture unit (spec 2.11.2); GL_ACTIVE_TEXTURE selects one.
  MatrixStack texture[kTextureUnitCount] = {
      MatrixStack{kTextureStackDepth}, MatrixStack{kTextureStackDepth},
      MatrixStack{kTextureStackDepth}, MatrixStack{kTextureStackDepth},
      MatrixStack{kTextureStackDepth}, MatrixStack{kTextureStackDepth},
      MatrixStack{kTextureStackDepth}, MatrixStack{kTextureStackDepth}};

  Viewport viewport;          // set to the framebuffer size when the context is created
  double depthNear = 0.0;     // glDepthRange, clamped to [0, 1]
  double depthFar = 1.0;

  // glClipPlane: plane equations in eye coordinates (transformed by the inverse of the
  // modelview matrix current when they were specified), and GL_CLIP_PLANEi enables as bits.
  double clipPlanes[raster::kMaxUserClipPlanes][4] = {};
  unsigned clipPlaneEnabled = 0;

  bool normalize = false;      // GL_NORMALIZE
  bool rescaleNormal = false;  // GL_RESCALE_NORMAL

  // The stack glMatrixMode selects; for GL_TEXTURE, that of the active texture unit.
  MatrixStack& currentStack(int activeTextureUnit) {
    return matrixMode == GL_PROJECTION ? projection
           : matrixMode == GL_TEXTURE  ? texture[activeTextureUnit]
                                       : modelview;
  }
};

}  // namespace glass::gl
