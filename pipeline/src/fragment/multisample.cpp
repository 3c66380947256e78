#include "fragment/multisample.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool queryMultisampleState(const Context& ctx, GLenum pname, StateValue& v) {
  const FragmentState& f = ctx.fragment;
  switch (pname) {
    case GL_SAMPLE_BUFFERS: case GL_SAMPLES: v.setIntegers({0}); return true;
    case GL_SAMPLE_COVERAGE_VALUE: v.setFloats({f.sampleCoverageValue}); return true;
    case GL_SAMPLE_COVERAGE_INVERT: v.setBooleans({f.sampleCoverageInvert}); return true;
    default: return false;
  }
}

}  // namespace glass::gl
