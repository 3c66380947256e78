// Multisampling (OpenGL 1.3, spec 3.2.1 and 4.1.3). glass's framebuffer has no multisample
// buffer (GL_SAMPLE_BUFFERS is 0, GL_SAMPLES 0), and the specification says that without one
// multisample rasterization and the sample coverage operations do not happen, whatever the
// enables. So glSampleCoverage and the four enables (GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
// GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE) only set state that glGet and glIsEnabled report
// and the attribute stack saves (GL_MULTISAMPLE_BIT, GL_ENABLE_BIT).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// glGet of GL_SAMPLE_BUFFERS, GL_SAMPLES, GL_SAMPLE_COVERAGE_VALUE and GL_SAMPLE_COVERAGE_INVERT.
// False when pname is none of these.
bool queryMultisampleState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
