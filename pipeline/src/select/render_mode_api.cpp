// glRenderMode, glSelectBuffer, glFeedbackBuffer, the name stack commands and glPassThrough
// (OpenGL 1.5 specification, sections 5.2 and 5.3).
//
// Display lists (spec 5.4): glRenderMode, glSelectBuffer and glFeedbackBuffer execute at once;
// glInitNames, glLoadName, glPushName, glPopName and glPassThrough are compiled. The name stack
// commands are ignored outside selection mode, glPassThrough outside feedback mode.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "select/render_mode.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::queryNow;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;
using glass::gl::SelectionState;

namespace {

// The name stack commands' common start: false when the command does nothing.
bool nameStackCommandApplies(Context& ctx) {
  if (rejectInsideBeginEnd(ctx)) return false;
  return ctx.renderMode.mode == GL_SELECT;
}

}  // namespace

extern "C" {

GLint glRenderMode(GLenum mode) {
  return queryNow(GLint(0), [=](Context& ctx) -> GLint {
    if (rejectInsideBeginEnd(ctx)) return 0;
    return glass::gl::setRenderMode(ctx, mode);
  });
}

void glSelectBuffer(GLsizei size, GLuint* buffer) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (size < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (ctx.renderMode.mode == GL_SELECT) return recordError(ctx, GL_INVALID_OPERATION);
    SelectionState& s = ctx.renderMode.selection;
    s.buffer = buffer;
    s.bufferSize = size;  // queried as given; nothing is stored through a null buffer
    s.bufferGiven = true;
    s.written = 0;
  });
}

void glFeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
        type != GL_4D_COLOR_TEXTURE) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    if (size < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (ctx.renderMode.mode == GL_FEEDBACK) return recordError(ctx, GL_INVALID_OPERATION);
    glass::gl::FeedbackState& f = ctx.renderMode.feedback;
    f.buffer = buffer;
    f.bufferSize = size;  // queried as given; nothing is stored through a null buffer
    f.bufferGiven = true;
    f.type = type;
    f.written = 0;
  });
}

void glInitNames(void) {
  compileOrExecute([](Context& ctx) {
    if (!nameStackCommandApplies(ctx)) return;
    glass::gl::writeHitRecord(ctx);
    ctx.renderMode.selection.nameStackDepth = 0;
  });
}

void glLoadName(GLuint name) {
  compileOrExecute([=](Context& ctx) {
    if (!nameStackCommandApplies(ctx)) return;
    SelectionState& s = ctx.renderMode.selection;
    if (s.nameStackDepth == 0) return recordError(ctx, GL_INVALID_OPERATION);
    glass::gl::writeHitRecord(ctx);
    s.nameStack[s.nameStackDepth - 1] = name;
  });
}

void glPushName(GLuint name) {
  compileOrExecute([=](Context& ctx) {
    if (!nameStackCommandApplies(ctx)) return;
    SelectionState& s = ctx.renderMode.selection;
    if (s.nameStackDepth >= glass::gl::kMaxNameStackDepth) {
      return recordError(ctx, GL_STACK_OVERFLOW);
    }
    glass::gl::writeHitRecord(ctx);
    s.nameStack[s.nameStackDepth++] = name;
  });
}

void glPopName(void) {
  compileOrExecute([](Context& ctx) {
    if (!nameStackCommandApplies(ctx)) return;
    SelectionState& s = ctx.renderMode.selection;
    if (s.nameStackDepth == 0) return recordError(ctx, GL_STACK_UNDERFLOW);
    glass::gl::writeHitRecord(ctx);
    --s.nameStackDepth;
  });
}

void glPassThrough(GLfloat token) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (ctx.renderMode.mode != GL_FEEDBACK) return;
    glass::gl::writeFeedbackValue(ctx, static_cast<float>(GL_PASS_THROUGH_TOKEN));
    glass::gl::writeFeedbackValue(ctx, token);
  });
}

}  // extern "C"
