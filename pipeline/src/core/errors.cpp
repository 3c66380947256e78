#include "core/errors.h"

#include "core/context.h"

namespace glass::gl {

void recordError(Context& ctx, GLenum error) {
  if (ctx.errors.error == GL_NO_ERROR) ctx.errors.error = error;
}

bool rejectInsideBeginEnd(Context& ctx) {
  if (!ctx.assembly.active) return false;
  recordError(ctx, GL_INVALID_OPERATION);
  return true;
}

}  // namespace glass::gl
