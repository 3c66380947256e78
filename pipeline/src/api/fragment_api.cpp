// Per-fragment operations and framebuffer control (spec 4.1, 4.2): scissor, alpha test, stencil,
// depth, blending, logic op, write masks, clear values and glClear. All compiled into display
// lists; none allowed between glBegin and glEnd.
#include <GL/gl.h>

#include <algorithm>

#include "core/context.h"
#include "fragment/blending.h"
#include "fragment/clear.h"
#include "fragment/comparison.h"
#include "fragment/logic_op.h"
#include "fragment/stencil_operation.h"
#include "lists/command_recording.h"

using glass::gl::Context;
using glass::gl::FragmentState;
using glass::gl::recordError;

namespace {

template <class Update>
void fragmentCommand(Update update) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    update(ctx, ctx.fragment);
  });
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

void blendFunc(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    using glass::gl::isBlendFactor;
    if (!isBlendFactor(srcRGB, true) || !isBlendFactor(dstRGB, false) ||
        !isBlendFactor(srcAlpha, true) || !isBlendFactor(dstAlpha, false)) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    f.blendSrcRGB = srcRGB;
    f.blendDstRGB = dstRGB;
    f.blendSrcAlpha = srcAlpha;
    f.blendDstAlpha = dstAlpha;
  });
}

}  // namespace

extern "C" {

void glScissor(GLint x, GLint y, GLsizei width, GLsizei height) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (width < 0 || height < 0) return recordError(ctx, GL_INVALID_VALUE);
    f.scissor = glass::gl::ScissorBox{x, y, width, height};
  });
}

void glAlphaFunc(GLenum func, GLclampf ref) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (!glass::gl::isComparisonFunc(func)) return recordError(ctx, GL_INVALID_ENUM);
    f.alphaFunc = func;
    f.alphaRef = clamp01(ref);
  });
}

void glStencilFunc(GLenum func, GLint ref, GLuint mask) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (!glass::gl::isComparisonFunc(func)) return recordError(ctx, GL_INVALID_ENUM);
    f.stencilFunc = func;
    f.stencilRef = std::clamp(ref, 0, 255);  // spec 4.1.5: clamped to [0, 2^s - 1]
    f.stencilValueMask = mask;
  });
}

void glStencilOp(GLenum fail, GLenum zfail, GLenum zpass) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    using glass::gl::isStencilOperation;
    if (!isStencilOperation(fail) || !isStencilOperation(zfail) || !isStencilOperation(zpass)) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    f.stencilFail = fail;
    f.stencilDepthFail = zfail;
    f.stencilDepthPass = zpass;
  });
}

void glStencilMask(GLuint mask) {
  fragmentCommand([=](Context&, FragmentState& f) { f.stencilWriteMask = mask; });
}

void glDepthFunc(GLenum func) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (!glass::gl::isComparisonFunc(func)) return recordError(ctx, GL_INVALID_ENUM);
    f.depthFunc = func;
  });
}

void glDepthMask(GLboolean flag) {
  fragmentCommand([=](Context&, FragmentState& f) { f.depthMask = flag != GL_FALSE; });
}

void glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  fragmentCommand([=](Context&, FragmentState& f) {
    f.colorMask[0] = r != GL_FALSE;
    f.colorMask[1] = g != GL_FALSE;
    f.colorMask[2] = b != GL_FALSE;
    f.colorMask[3] = a != GL_FALSE;
  });
}

void glBlendFunc(GLenum sfactor, GLenum dfactor) { blendFunc(sfactor, dfactor, sfactor, dfactor); }

void glBlendFuncSeparate(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha) {
  blendFunc(srcRGB, dstRGB, srcAlpha, dstAlpha);
}

void glBlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  fragmentCommand([=](Context&, FragmentState& f) {
    f.blendColor[0] = clamp01(r);
    f.blendColor[1] = clamp01(g);
    f.blendColor[2] = clamp01(b);
    f.blendColor[3] = clamp01(a);
  });
}

void glBlendEquation(GLenum mode) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (!glass::gl::isBlendEquation(mode)) return recordError(ctx, GL_INVALID_ENUM);
    f.blendEquation = mode;
  });
}

void glLogicOp(GLenum opcode) {
  fragmentCommand([=](Context& ctx, FragmentState& f) {
    if (!glass::gl::isLogicOp(opcode)) return recordError(ctx, GL_INVALID_ENUM);
    f.logicOp = opcode;
  });
}

void glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  fragmentCommand([=](Context&, FragmentState& f) {
    f.clearColor[0] = clamp01(r);
    f.clearColor[1] = clamp01(g);
    f.clearColor[2] = clamp01(b);
    f.clearColor[3] = clamp01(a);
  });
}

void glClearDepth(GLclampd depth) {
  fragmentCommand([=](Context&, FragmentState& f) { f.clearDepth = std::clamp(depth, 0.0, 1.0); });
}

void glClearStencil(GLint s) {
  fragmentCommand([=](Context&, FragmentState& f) { f.clearStencil = s; });
}

void glClear(GLbitfield mask) {
  fragmentCommand([=](Context& ctx, FragmentState&) {
    constexpr GLbitfield kBuffers =
        GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if (mask & ~kBuffers) return recordError(ctx, GL_INVALID_VALUE);
    glass::gl::clearBuffers(ctx, mask);
  });
}

}  // extern "C"
