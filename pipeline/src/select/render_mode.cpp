// glRenderMode (OpenGL 1.5 specification, sections 5.2 and 5.3).
#include "core/context.h"
#include "select/render_mode.h"

namespace glass::gl {

namespace {

void resetSelection(SelectionState& s) {
  s.written = 0;
  s.hits = 0;
  s.nameStackDepth = 0;
  s.hitFlag = false;
  s.hitMinDepth = 1.0f;
  s.hitMaxDepth = 0.0f;
}

}  // namespace

GLint setRenderMode(Context& ctx, GLenum mode) {
  RenderModeState& r = ctx.renderMode;
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
    recordError(ctx, GL_INVALID_ENUM);
    return 0;
  }
  // Spec 5.2, 5.3: selection and feedback need their buffer first.
  if ((mode == GL_SELECT && !r.selection.bufferGiven) ||
      (mode == GL_FEEDBACK && !r.feedback.bufferGiven)) {
    recordError(ctx, GL_INVALID_OPERATION);
    return 0;
  }

  GLint result = 0;
  if (r.mode == GL_SELECT) {
    // Leaving selection: the pending hit is written, the hit count returned (-1 when the records
    // did not fit), and the name stack emptied.
    SelectionState& s = r.selection;
    writeHitRecord(ctx);
    result = s.written > s.bufferSize ? -1 : s.hits;
    resetSelection(s);
  } else if (r.mode == GL_FEEDBACK) {
    FeedbackState& f = r.feedback;
    result = f.written > f.bufferSize ? -1 : static_cast<GLint>(f.written);
    f.written = 0;
  }

  if (mode == GL_SELECT) resetSelection(r.selection);
  if (mode == GL_FEEDBACK) r.feedback.written = 0;
  r.mode = mode;
  return result;
}

}  // namespace glass::gl
