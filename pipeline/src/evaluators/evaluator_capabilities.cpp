// The evaluators' enables and glGet state (spec 5.1, table 6.24).
#include "core/context.h"
#include "core/state_value.h"
#include "evaluators/evaluator_commands.h"
#include "evaluators/map_targets.h"

namespace glass::gl {

namespace {

// The flag of GL_MAP1_*, GL_MAP2_* or GL_AUTO_NORMAL, or nullptr; Attributes is
// EvaluatorAttributes, const or not.
template <class Attributes>
auto evaluatorFlag(Attributes& a, GLenum cap) -> decltype(&a.autoNormal) {
  MapKind kind;
  if (map1Kind(cap, kind)) return &a.map1Enabled[mapIndex(kind)];
  if (map2Kind(cap, kind)) return &a.map2Enabled[mapIndex(kind)];
  if (cap == GL_AUTO_NORMAL) return &a.autoNormal;
  return nullptr;
}

}  // namespace

bool setEvaluatorCapability(Context& ctx, GLenum cap, bool enabled) {
  bool* flag = evaluatorFlag(ctx.evaluators.attributes, cap);
  if (!flag) return false;
  *flag = enabled;
  return true;
}

bool getEvaluatorCapability(const Context& ctx, GLenum cap, bool& enabled) {
  const bool* flag = evaluatorFlag(ctx.evaluators.attributes, cap);
  if (!flag) return false;
  enabled = *flag;
  return true;
}

bool queryEvaluatorState(const Context& ctx, GLenum pname, StateValue& value) {
  const EvaluatorAttributes& a = ctx.evaluators.attributes;
  switch (pname) {
    case GL_MAX_EVAL_ORDER: value.setIntegers({double(kMaxEvalOrder)}); return true;
    case GL_MAP1_GRID_DOMAIN: value.setFloats({a.grid1.u1, a.grid1.u2}); return true;
    case GL_MAP1_GRID_SEGMENTS: value.setIntegers({double(a.grid1.segments)}); return true;
    case GL_MAP2_GRID_DOMAIN: value.setFloats({a.grid2.u1, a.grid2.u2, a.grid2.v1, a.grid2.v2}); return true;
    case GL_MAP2_GRID_SEGMENTS:
      value.setIntegers({double(a.grid2.segmentsU), double(a.grid2.segmentsV)});
      return true;
    default: return false;
  }
}

}  // namespace glass::gl
