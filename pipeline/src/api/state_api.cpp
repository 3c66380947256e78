// State and errors: glEnable, glDisable, glIsEnabled, glGetError, glGet*, glGetString, glHint,
// glFinish, glFlush (spec 2.5, 5.5, 5.6, 6.1).
#include <GL/gl.h>

#include <cmath>
#include <limits>

#include "core/capabilities.h"
#include "core/context.h"
#include "core/gl_strings.h"
#include "core/state_query.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::queryNow;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;
using glass::gl::StateValue;

namespace {

void setCapabilityCommand(GLenum cap, bool enabled) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (!glass::gl::setCapability(ctx, cap, enabled)) recordError(ctx, GL_INVALID_ENUM);
  });
}

// Looks pname up for a glGet*v; false (after recording the error) when it cannot be answered.
bool lookUp(Context& ctx, GLenum pname, StateValue& value) {
  if (rejectInsideBeginEnd(ctx)) return false;
  if (!glass::gl::queryState(ctx, pname, value)) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  return true;
}

// Spec 6.1.2: colours, normals, depth range and depth clear values map [-1, 1] linearly onto the
// integer range, 1.0 to the most positive and -1.0 to the most negative integer:
// i = ((2^32 - 1) c - 1) / 2, rounded to nearest with halves upward, so that 0.0 gives 0.
GLint normalizedToInteger(double value) {
  const double scaled = std::floor(4294967295.0 * value / 2.0);
  if (std::isnan(scaled)) return 0;  // converting NaN is undefined; a NaN state value reads as 0
  if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(scaled);
}

GLint floatToInteger(double value) {
  if (std::isnan(value)) return 0;
  if (value >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (value <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::lround(value));
}

}  // namespace

extern "C" {

void glEnable(GLenum cap) { setCapabilityCommand(cap, true); }
void glDisable(GLenum cap) { setCapabilityCommand(cap, false); }

GLboolean glIsEnabled(GLenum cap) {
  return queryNow(GLboolean(GL_FALSE), [=](Context& ctx) -> GLboolean {
    if (rejectInsideBeginEnd(ctx)) return GL_FALSE;
    bool enabled = false;
    if (!glass::gl::getCapability(ctx, cap, enabled)) {
      recordError(ctx, GL_INVALID_ENUM);
      return GL_FALSE;
    }
    return enabled ? GL_TRUE : GL_FALSE;
  });
}

GLenum glGetError(void) {
  return queryNow(GLenum(GL_NO_ERROR), [](Context& ctx) -> GLenum {
    if (rejectInsideBeginEnd(ctx)) return GL_NO_ERROR;
    const GLenum error = ctx.errors.error;
    ctx.errors.error = GL_NO_ERROR;
    return error;
  });
}

void glGetBooleanv(GLenum pname, GLboolean* params) {
  executeNow([=](Context& ctx) {
    StateValue v;
    if (!lookUp(ctx, pname, v) || !params) return;
    for (int i = 0; i < v.count; ++i) params[i] = v.values[i] != 0.0 ? GL_TRUE : GL_FALSE;
  });
}

void glGetIntegerv(GLenum pname, GLint* params) {
  executeNow([=](Context& ctx) {
    StateValue v;
    if (!lookUp(ctx, pname, v) || !params) return;
    for (int i = 0; i < v.count; ++i) {
      switch (v.kind) {
        case StateValue::Kind::Color: params[i] = normalizedToInteger(v.values[i]); break;
        case StateValue::Kind::Float: params[i] = floatToInteger(v.values[i]); break;
        default: params[i] = static_cast<GLint>(static_cast<long long>(v.values[i])); break;
      }
    }
  });
}

void glGetFloatv(GLenum pname, GLfloat* params) {
  executeNow([=](Context& ctx) {
    StateValue v;
    if (!lookUp(ctx, pname, v) || !params) return;
    for (int i = 0; i < v.count; ++i) params[i] = static_cast<GLfloat>(v.values[i]);
  });
}

void glGetDoublev(GLenum pname, GLdouble* params) {
  executeNow([=](Context& ctx) {
    StateValue v;
    if (!lookUp(ctx, pname, v) || !params) return;
    for (int i = 0; i < v.count; ++i) params[i] = v.values[i];
  });
}

const GLubyte* glGetString(GLenum name) {
  return queryNow(static_cast<const GLubyte*>(nullptr), [=](Context& ctx) -> const GLubyte* {
    if (rejectInsideBeginEnd(ctx)) return nullptr;
    const char* text = glass::gl::glString(name);
    if (!text) recordError(ctx, GL_INVALID_ENUM);
    return reinterpret_cast<const GLubyte*>(text);
  });
}

void glHint(GLenum target, GLenum mode) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    GLenum* hint = ctx.hints.find(target);
    if (!hint || (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)) {
      recordError(ctx, GL_INVALID_ENUM);
      return;
    }
    *hint = mode;
  });
}

// Draws are queued and rasterized later (primitive/queued_drawing.h). Both commands rasterize
// what is queued and return when it is in the framebuffer: glFinish must (spec 5.5), and glFlush,
// which need only start it, does the same, since nothing else would start it in finite time.
// Then the embedding that shows the framebuffer elsewhere is told, through the one hook
// Context::afterFlush: a single-buffered GLUT window shows its picture (glassSetFlushCallback),
// an OSMesa context fills the caller's buffer.
namespace {
void finishAndShow() {
  executeNow([](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    glass::gl::finishQueuedDrawing(ctx);
    if (ctx.afterFlush) ctx.afterFlush(ctx);
  });
}
}  // namespace

void glFinish(void) { finishAndShow(); }
void glFlush(void) { finishAndShow(); }

}  // extern "C"
