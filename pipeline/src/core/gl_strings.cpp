#include "core/gl_strings.h"

#include <string>

#include "core/fast_paths.h"

namespace glass::gl {

namespace {

// "glass software rasterizer (SIMD: <target>)", or "(fast paths off)" with GLASS_FAST_PATHS=0:
// what a benchmark of the renderer should report beside its figures.
const char* rendererString() {
  static const std::string renderer =
      std::string("glass software rasterizer (") +
      (fastPathsEnabled() ? std::string("SIMD: ") + simdTargetName() : std::string("fast paths off")) +
      ")";
  return renderer.c_str();
}

}  // namespace

const char* glString(GLenum name) {
  switch (name) {
    case GL_VENDOR:
      return "glass";
    case GL_RENDERER:
      return rendererString();
    case GL_VERSION:
      // "<major>.<minor> <vendor information>" (spec 6.1.11). glass implements the OpenGL 1.3
      // fixed-function pipeline in part; the README lists what works.
      return "1.3 glass 0.1.0 (a subset of OpenGL 1.3)";
    case GL_EXTENSIONS:
      // Space-separated. Stages add the extensions they implement here.
      return "GL_EXT_blend_color GL_EXT_blend_func_separate GL_EXT_blend_minmax "
             "GL_EXT_blend_subtract GL_EXT_stencil_wrap GL_EXT_rescale_normal GL_WIN_phong_shading "
             "GL_ARB_texture_mirrored_repeat GL_SGIS_generate_mipmap GL_GLASS_bump_map";
    default:
      return nullptr;
  }
}

}  // namespace glass::gl
