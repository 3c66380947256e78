// Selection (OpenGL 1.5 specification, section 5.2): hit records.
#include <cmath>

#include "core/context.h"
#include "select/render_mode.h"

namespace glass::gl {

namespace {

void writeSelectionValue(SelectionState& s, GLuint value) {
  if (s.written < s.bufferSize && s.buffer != nullptr) s.buffer[s.written] = value;
  ++s.written;
}

// Spec 5.2: the depth values of a hit record are window z in [0, 1] "multiplied by 2^32 - 1 and
// rounded to the nearest unsigned integer". (Mesa truncates float(2^32) * z instead, which is
// the same value for z below 1/2 and one more above.)
GLuint scaledDepth(float z) {
  const double scaled = std::nearbyint(static_cast<double>(z) * 4294967295.0);
  if (!(scaled > 0.0)) return 0;
  if (scaled >= 4294967295.0) return 0xFFFFFFFFu;
  return static_cast<GLuint>(scaled);
}

}  // namespace

void recordHit(Context& ctx, float windowZ) {
  SelectionState& s = ctx.renderMode.selection;
  s.hitFlag = true;
  if (windowZ < s.hitMinDepth) s.hitMinDepth = windowZ;
  if (windowZ > s.hitMaxDepth) s.hitMaxDepth = windowZ;
}

void writeHitRecord(Context& ctx) {
  SelectionState& s = ctx.renderMode.selection;
  if (!s.hitFlag) return;
  // A hit record: the number of names, the minimum and maximum depth, then the names from the
  // bottom of the stack up (spec 5.2).
  writeSelectionValue(s, static_cast<GLuint>(s.nameStackDepth));
  writeSelectionValue(s, scaledDepth(s.hitMinDepth));
  writeSelectionValue(s, scaledDepth(s.hitMaxDepth));
  for (int i = 0; i < s.nameStackDepth; ++i) writeSelectionValue(s, s.nameStack[i]);
  ++s.hits;
  s.hitFlag = false;
  s.hitMinDepth = 1.0f;
  s.hitMaxDepth = 0.0f;
}

}  // namespace glass::gl
