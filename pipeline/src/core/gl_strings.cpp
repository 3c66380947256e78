#include "core/gl_strings.h"

#include <string>

#include "core/fast_paths.h"

namespace glass::gl {

namespace {

// Every extension whose functionality glass implements, and no other: <GL/glext.h> (and <GL/gl.h>
// for GL_ARB_multitexture and glass's own, <GL/glass_statistics.h> for its statistics queries)
// declares exactly these, and tests/api_coverage checks that the lists agree. Most are the GL
// 1.2-1.4 core features under the names programs of the time use; the last three are glass's own
// (docs/lighting.md, docs/texturing.md, docs/teaching.md).
constexpr const char* kExtensions =
    "GL_ARB_depth_texture GL_ARB_imaging GL_ARB_multitexture GL_ARB_multisample GL_ARB_shadow "
    "GL_ARB_point_parameters GL_ARB_texture_border_clamp "
    "GL_ARB_texture_compression GL_ARB_texture_cube_map GL_ARB_texture_env_add "
    "GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 "
    "GL_ARB_texture_mirrored_repeat GL_ARB_transpose_matrix GL_ARB_window_pos "
    "GL_EXT_bgra GL_EXT_blend_color GL_EXT_blend_func_separate GL_EXT_blend_logic_op "
    "GL_EXT_blend_minmax GL_EXT_blend_subtract GL_EXT_copy_texture GL_EXT_draw_range_elements "
    "GL_EXT_fog_coord GL_EXT_multi_draw_arrays GL_EXT_packed_pixels GL_EXT_point_parameters "
    "GL_EXT_rescale_normal GL_EXT_secondary_color GL_EXT_separate_specular_color "
    "GL_EXT_shadow_funcs "
    "GL_EXT_stencil_wrap GL_EXT_subtexture GL_EXT_texture3D GL_EXT_texture_cube_map "
    "GL_EXT_texture_env_add GL_EXT_texture_env_combine GL_EXT_texture_lod_bias "
    "GL_EXT_texture_object GL_IBM_texture_mirrored_repeat GL_NV_blend_square "
    "GL_SGIS_generate_mipmap GL_SGIS_texture_edge_clamp GL_SGIS_texture_lod "
    "GL_WIN_phong_shading GL_GLASS_bump_map GL_GLASS_pipeline_statistics";

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
      // "<major>.<minor> <vendor information>" (spec 6.1.11). Every feature OpenGL 1.4 added
      // (appendix I) is there; the README lists what works and what is not done.
      return "1.4 glass 0.1.0";
    case GL_EXTENSIONS:
      return kExtensions;
    default:
      return nullptr;
  }
}

}  // namespace glass::gl
