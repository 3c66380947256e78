// A texture object (OpenGL 1.5 specification, section 3.8.12): its images, one per mipmap level,
// and its parameters (glTexParameter, section 3.8.4, table 3.19). Member initialisers are the
// defaults of table 6.16.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>

#include "texture/texture_image.h"

namespace glass::gl {

// The glTexParameter state of a texture object.
struct SamplerParameters {
  GLenum minFilter = GL_NEAREST_MIPMAP_LINEAR;
  GLenum magFilter = GL_LINEAR;
  GLenum wrapS = GL_REPEAT;
  GLenum wrapT = GL_REPEAT;
  GLenum wrapR = GL_REPEAT;
  float borderColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  float minLod = -1000.0f;
  float maxLod = 1000.0f;
  float lodBias = 0.0f;  // GL_TEXTURE_LOD_BIAS of the object (OpenGL 1.4)
  int baseLevel = 0;
  int maxLevel = 1000;
  bool generateMipmap = false;
  float priority = 1.0f;
  // Depth textures (OpenGL 1.4, 3.8.4 and 3.8.13; texture/depth_comparison.h).
  GLenum compareMode = GL_NONE;           // GL_TEXTURE_COMPARE_MODE
  GLenum compareFunc = GL_LEQUAL;         // GL_TEXTURE_COMPARE_FUNC
  GLenum depthTextureMode = GL_LUMINANCE;  // GL_DEPTH_TEXTURE_MODE
};

// True for the four minification filters that use mipmaps.
bool isMipmapFilter(GLenum minFilter);

// A cube map (OpenGL 1.3, section 3.8.6) has six faces, in the order of their targets:
// GL_TEXTURE_CUBE_MAP_POSITIVE_X, NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z.
inline constexpr int kCubeFaceCount = 6;
// The face index 0..5 of a face target, -1 for any other value.
inline int cubeFaceOf(GLenum target) {
  return target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z
             ? static_cast<int>(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X)
             : -1;
}

// Named objects are made by TextureNames, always in a shared_ptr; the default objects (name 0)
// are members of TextureState.
struct TextureObject : std::enable_shared_from_this<TextureObject> {
  GLuint name = 0;
  // GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D or GL_TEXTURE_CUBE_MAP once first bound; 0
  // before (spec 3.8.12: a name becomes a texture of the target it is first bound to).
  GLenum target = 0;
  TextureImage levels[kMaxTextureLevels];  // a 1D or 2D texture's images; face 0 of a cube map
  TextureImage otherFaces[kCubeFaceCount - 1][kMaxTextureLevels];  // faces 1..5 of a cube map
  SamplerParameters params;

  // Whether the object can be sampled with its current filter (spec 3.8.10, "Texture
  // Completeness"): the base level exists; with a mipmap minification filter also every level
  // from the base to q = min(p, maxLevel), p = floor(log2(max(w_b, h_b))) + base, exists with
  // size max(1, floor(w_b / 2^(i - base))) x max(1, floor(h_b / 2^(i - base))), the same
  // internal format and the same border. An incomplete texture turns texturing off for its unit
  // (spec 3.8.15). Recomputed by updateCompleteness() after every change of images or
  // parameters.
  bool complete = false;
  // q, the last level sampling may use (valid when complete).
  int lastLevel = 0;

  // Values every lookup needs, derived from the parameters and the base level's format by
  // updateCompleteness() so that they are not recomputed per fragment.
  struct Sampling {
    // The border texel as a colour texel: components rounded to 8 bits, as the texels of the
    // images are.
    uint8_t borderBytes[4] = {0, 0, 0, 0};
    float switchOverPoint = 0.0f;                 // c of spec 3.8.9
  } sampling;

  void updateCompleteness();

  // The base level image (valid when complete); face 0's for a cube map.
  const TextureImage& baseImage() const { return levels[params.baseLevel]; }
  // Level `level` of face `face` (0 for a 1D or 2D texture).
  TextureImage& image(int face, int level) {
    return face == 0 ? levels[level] : otherFaces[face - 1][level];
  }
  const TextureImage& image(int face, int level) const {
    return face == 0 ? levels[level] : otherFaces[face - 1][level];
  }
  int faceCount() const { return target == GL_TEXTURE_CUBE_MAP ? kCubeFaceCount : 1; }
};

// The last level index of a full mipmap chain starting at base with a base image of the given
// size: base + floor(log2(max(width, height, depth))), clamped to the levels glass stores.
int lastMipmapLevel(int base, int width, int height, int depth = 1);

}  // namespace glass::gl
