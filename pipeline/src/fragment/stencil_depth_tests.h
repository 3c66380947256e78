// The stencil test, the depth test and the writes they imply, for one fragment (spec 4.1.5 and
// 4.1.6), in the specification's order: a fragment that fails the stencil test gets the
// stencil-fail operation and goes no further; one that passes it and fails the depth test gets
// the depth-fail operation; one that passes both writes its depth (when the depth mask is on)
// and gets the depth-pass operation. The reference fragment path (fragment_processor.cpp) and the
// block kernels (block_kernels.cpp) both call this, so they cannot differ.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "fragment/comparison.h"
#include "fragment/stencil_operation.h"

namespace glass::gl {

struct StencilDepthSettings {
  bool stencilTest = false;
  GLenum stencilFunc = GL_ALWAYS;
  uint8_t stencilRef = 0;
  unsigned stencilValueMask = 0xFF;
  unsigned stencilWriteMask = 0xFF;
  GLenum stencilFail = GL_KEEP, stencilDepthFail = GL_KEEP, stencilDepthPass = GL_KEEP;

  bool depthTest = false;
  GLenum depthFunc = GL_LESS;
  bool depthMask = true;

  bool operator==(const StencilDepthSettings&) const = default;
};

enum class StencilDepthOutcome { StencilFailed, DepthFailed, Passed };

// stencil: the fragment's stencil value (null when the stencil test is off); depth: its stored
// depth (read only when the depth test is on); fragmentDepth: the fragment's window depth.
inline StencilDepthOutcome testStencilAndDepth(const StencilDepthSettings& s, uint8_t* stencil,
                                               uint32_t* depth, uint32_t fragmentDepth) {
  if (stencil) {
    const unsigned stored = *stencil & s.stencilValueMask;
    if (!passesComparison(s.stencilFunc, s.stencilRef & s.stencilValueMask, stored)) {
      writeStencil(*stencil, applyStencilOperation(s.stencilFail, *stencil, s.stencilRef), s.stencilWriteMask);
      return StencilDepthOutcome::StencilFailed;
    }
  }
  if (s.depthTest) {
    if (!passesComparison(s.depthFunc, fragmentDepth, *depth)) {
      if (stencil) {
        writeStencil(*stencil, applyStencilOperation(s.stencilDepthFail, *stencil, s.stencilRef),
                     s.stencilWriteMask);
      }
      return StencilDepthOutcome::DepthFailed;
    }
    if (s.depthMask) *depth = fragmentDepth;
  }
  if (stencil) {
    writeStencil(*stencil, applyStencilOperation(s.stencilDepthPass, *stencil, s.stencilRef),
                 s.stencilWriteMask);
  }
  return StencilDepthOutcome::Passed;
}

}  // namespace glass::gl
