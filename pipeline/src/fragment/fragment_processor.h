// The per-fragment stage (spec chapter 4.1): receives the rasterizer's fragments and applies, in
// the specification's order,
//   per-fragment lighting (GL_PHONG_WIN), texturing, colour sum, fog    (chapter 3.8-3.10)
//   antialiasing coverage times alpha (3.11; smooth points and lines)
//   scissor test      (done by the rasterizer's bounds)
//   alpha test, stencil test, depth test (and the stencil and depth writes they imply)
//   blending or logic op, then the colour write masks.
// The state it reads cannot change between glBegin and glEnd, so prepare() captures it once per
// glBegin and the per-fragment loop only tests flags.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "fragment/blending.h"
#include "glass/raster/fragment.h"

namespace glass::gl {

struct Context;

class FragmentProcessor final : public raster::FragmentSink {
 public:
  // phong: the vertex stage passes eye position and normal (GL_PHONG_WIN with lighting on).
  void prepare(Context& ctx, bool phong);
  void processFragments(const raster::FragmentBatch& batch) override;
  // The same for fragments of an antialiased primitive: coverage[i] (smooth_coverage.h)
  // multiplies the alpha of fragment i once its colour is final (spec 3.11, "Antialiasing
  // Application").
  void processFragments(const raster::FragmentBatch& batch, const float* coverage);

 private:
  Context* ctx_ = nullptr;

  bool phong_ = false;
  bool bumpMapping_ = false;       // GL_GLASS_bump_map perturbs the normal before Phong lighting
  bool texturing_ = false;
  bool secondaryVarying_ = false;  // separate specular colour in varyings 4-7
  bool colorSum_ = false;          // lit with separate specular, or unlit with GL_COLOR_SUM
  bool fog_ = false;

  bool alphaTest_ = false;
  GLenum alphaFunc_ = GL_ALWAYS;
  uint8_t alphaRefByte_ = 0;  // the reference as the colour buffer's 8-bit value

  bool stencilTest_ = false;
  GLenum stencilFunc_ = GL_ALWAYS;
  uint8_t stencilRef_ = 0;
  unsigned stencilValueMask_ = 0xFF;
  unsigned stencilWriteMask_ = 0xFF;
  GLenum stencilFail_ = GL_KEEP, stencilDepthFail_ = GL_KEEP, stencilDepthPass_ = GL_KEEP;

  bool depthTest_ = false;
  GLenum depthFunc_ = GL_LESS;
  bool depthMask_ = true;

  bool blend_ = false;
  BlendSettings blendSettings_;
  bool logicOp_ = false;
  GLenum logicOpMode_ = GL_COPY;
  bool colorMask_[4] = {true, true, true, true};
  bool writesColor_ = true;        // some channel unmasked and glDrawBuffer not GL_NONE
  bool allChannels_ = true;
};

}  // namespace glass::gl
