// glSampleCoverage (OpenGL 1.3, spec 4.1.3): the coverage value and inversion of
// GL_SAMPLE_COVERAGE, kept for glGet and the attribute stack (fragment/multisample.h).
#include <GL/gl.h>

#include <algorithm>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::Context;

extern "C" {

void glSampleCoverage(GLclampf value, GLboolean invert) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    ctx.fragment.sampleCoverageValue = std::clamp(value, 0.0f, 1.0f);
    ctx.fragment.sampleCoverageInvert = invert != GL_FALSE;
  });
}

}  // extern "C"
