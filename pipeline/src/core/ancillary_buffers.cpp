#include "core/ancillary_buffers.h"

#include "core/context.h"

namespace glass::gl {

bool hasBufferToRead(const Context& ctx, GLenum formatOrType) {
  switch (formatOrType) {
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH: return ctx.buffers.depth;
    case GL_STENCIL_INDEX:
    case GL_STENCIL: return ctx.buffers.stencil;
    default: return true;
  }
}

bool depthTestActive(const Context& ctx) { return ctx.fragment.depthTest && ctx.buffers.depth; }

bool stencilTestActive(const Context& ctx) { return ctx.fragment.stencilTest && ctx.buffers.stencil; }

}  // namespace glass::gl
