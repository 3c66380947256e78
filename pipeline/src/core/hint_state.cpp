#include "core/hint_state.h"

namespace glass::gl {

GLenum* HintState::find(GLenum target) {
  switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: return &perspectiveCorrection;
    case GL_POINT_SMOOTH_HINT: return &pointSmooth;
    case GL_LINE_SMOOTH_HINT: return &lineSmooth;
    case GL_POLYGON_SMOOTH_HINT: return &polygonSmooth;
    case GL_FOG_HINT: return &fog;
    case GL_GENERATE_MIPMAP_HINT: return &generateMipmap;
    case GL_TEXTURE_COMPRESSION_HINT: return &textureCompression;
    case GL_PHONG_HINT_WIN: return &phong;
    default: return nullptr;
  }
}

}  // namespace glass::gl
