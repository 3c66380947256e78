// Feedback (OpenGL 1.5 specification, section 5.3): values written to the feedback buffer.
#include "core/context.h"
#include "select/render_mode.h"

namespace glass::gl {

void writeFeedbackValue(Context& ctx, float value) {
  FeedbackState& f = ctx.renderMode.feedback;
  if (f.written < f.bufferSize && f.buffer != nullptr) f.buffer[f.written] = value;
  ++f.written;
}

void writeFeedbackVertex(Context& ctx, const float window[4], const float color[4],
                         const float texCoord[4]) {
  // Table 5.2: which values each feedback type writes per vertex (k = 4 colour values in RGBA
  // mode).
  const GLenum type = ctx.renderMode.feedback.type;
  const bool z = type != GL_2D;
  const bool w = type == GL_4D_COLOR_TEXTURE;
  const bool withColor = type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE || w;
  const bool withTexture = type == GL_3D_COLOR_TEXTURE || w;
  writeFeedbackValue(ctx, window[0]);
  writeFeedbackValue(ctx, window[1]);
  if (z) writeFeedbackValue(ctx, window[2]);
  if (w) writeFeedbackValue(ctx, window[3]);
  if (withColor) {
    for (int i = 0; i < 4; ++i) writeFeedbackValue(ctx, color[i]);
  }
  if (withTexture) {
    for (int i = 0; i < 4; ++i) writeFeedbackValue(ctx, texCoord[i]);
  }
}

void recordPixelCommand(Context& ctx, GLenum token) {
  if (ctx.renderMode.mode != GL_FEEDBACK) return;
  const RasterPositionState& r = ctx.rasterPosition;
  writeFeedbackValue(ctx, static_cast<float>(token));
  writeFeedbackVertex(ctx, r.window, r.color, r.texCoord[0]);
}

}  // namespace glass::gl
