#include "select/primitive_recorder.h"

#include "core/context.h"
#include "select/render_mode.h"
#include "vertex/varyings.h"

namespace glass::gl {

void PrimitiveRecorder::prepare(Context& ctx, bool texCoordVaryings) {
  ctx_ = &ctx;
  selecting_ = ctx.renderMode.mode == GL_SELECT;
  texCoordVaryings_ = texCoordVaryings;
}

void PrimitiveRecorder::vertex(const raster::WindowVertex& v) {
  if (selecting_) {
    recordHit(*ctx_, v.z);
    return;
  }
  // Spec 5.3: window coordinates, and w the clip coordinate w_c = 1 / (1 / w_c).
  const float window[4] = {v.x, v.y, v.z, 1.0f / v.invW};
  const float* texCoord =
      texCoordVaryings_ ? v.varyings + varying::kTexCoord : ctx_->current.texCoord[0];
  writeFeedbackVertex(*ctx_, window, v.varyings + varying::kPrimaryColor, texCoord);
}

void PrimitiveRecorder::point(const raster::WindowVertex& v) {
  if (!selecting_) writeFeedbackValue(*ctx_, static_cast<float>(GL_POINT_TOKEN));
  vertex(v);
}

void PrimitiveRecorder::line(const raster::WindowVertex& a, const raster::WindowVertex& b,
                             bool startsLine) {
  if (!selecting_) {
    writeFeedbackValue(*ctx_, static_cast<float>(startsLine ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN));
  }
  vertex(a);
  vertex(b);
}

void PrimitiveRecorder::polygon(const raster::WindowVertex* v, int count) {
  for (int i = 1; i + 1 < count; ++i) {
    if (!selecting_) {
      writeFeedbackValue(*ctx_, static_cast<float>(GL_POLYGON_TOKEN));
      writeFeedbackValue(*ctx_, 3.0f);
    }
    vertex(v[0]);
    vertex(v[i]);
    vertex(v[i + 1]);
  }
}

}  // namespace glass::gl
