// glHint targets (spec 5.6, table 6.31). Hints never change glass's results; they are stored
// and returned by glGet.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct HintState {
  GLenum perspectiveCorrection = GL_DONT_CARE;
  GLenum pointSmooth = GL_DONT_CARE;
  GLenum lineSmooth = GL_DONT_CARE;
  GLenum polygonSmooth = GL_DONT_CARE;
  GLenum fog = GL_DONT_CARE;
  GLenum generateMipmap = GL_DONT_CARE;
  GLenum textureCompression = GL_DONT_CARE;
  GLenum phong = GL_DONT_CARE;  // GL_PHONG_HINT_WIN

  // The stored hint of target, or nullptr for an unknown target.
  GLenum* find(GLenum target);
};

}  // namespace glass::gl
