// Per-fragment operations and framebuffer control (spec 4.1 and 4.2; tables 6.19-6.21): scissor,
// alpha test, stencil, depth, blending, logic op, write masks and clear values.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct ScissorBox {
  int x = 0, y = 0, width = 0, height = 0;
};

struct FragmentState {
  bool scissorTest = false;
  ScissorBox scissor;                // set to the framebuffer size when the context is created

  bool alphaTest = false;
  GLenum alphaFunc = GL_ALWAYS;
  float alphaRef = 0.0f;             // clamped to [0, 1]

  bool stencilTest = false;
  GLenum stencilFunc = GL_ALWAYS;
  int stencilRef = 0;                // clamped to [0, 255]
  GLuint stencilValueMask = ~0u;
  GLenum stencilFail = GL_KEEP;
  GLenum stencilDepthFail = GL_KEEP;
  GLenum stencilDepthPass = GL_KEEP;
  GLuint stencilWriteMask = ~0u;

  bool depthTest = false;
  GLenum depthFunc = GL_LESS;
  bool depthMask = true;

  bool blend = false;
  GLenum blendSrcRGB = GL_ONE;
  GLenum blendDstRGB = GL_ZERO;
  GLenum blendSrcAlpha = GL_ONE;
  GLenum blendDstAlpha = GL_ZERO;
  GLenum blendEquation = GL_FUNC_ADD;
  float blendColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};

  bool colorLogicOp = false;         // GL_COLOR_LOGIC_OP
  bool indexLogicOp = false;         // GL_INDEX_LOGIC_OP: colour index mode only, no effect
  GLenum logicOp = GL_COPY;

  bool dither = true;                // no effect on an 8-bit colour buffer
  bool colorMask[4] = {true, true, true, true};

  float clearColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  double clearDepth = 1.0;
  int clearStencil = 0;

  // Colour index mode only (core/color_index.h): kept and queried, no effect in RGBA mode.
  float clearIndex = 0.0f;           // glClearIndex
  GLuint indexMask = ~0u;            // glIndexMask

  // glDrawBuffer (fragment/buffer_selection.h): GL_NONE writes no colour at all.
  GLenum drawBuffer = GL_FRONT;

  // Multisampling (OpenGL 1.3, spec 3.2.1, 4.1.3; fragment/multisample.h): glass's framebuffer
  // has no sample buffers, so these are kept and queried but change no fragment.
  bool multisample = true;           // GL_MULTISAMPLE
  bool sampleAlphaToCoverage = false;
  bool sampleAlphaToOne = false;
  bool sampleCoverage = false;
  float sampleCoverageValue = 1.0f;  // glSampleCoverage, clamped to [0, 1]
  bool sampleCoverageInvert = false;
};

}  // namespace glass::gl
