// The imaging subset's state that glGet, glIsEnabled, glEnable and glPixelTransfer reach
// (OpenGL 1.4 specification, tables 6.18-6.22): the post-convolution and post-colour-matrix
// scales and biases, and the eight enables. The colour matrix stack is answered with the other
// matrix stacks (core/state_query.cpp).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct ImagingState;
struct StateValue;

// The scales and biases; false when pname is none of them.
bool queryImagingState(const Context& ctx, GLenum pname, StateValue& value);

// The flag of GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE,
// GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D, GL_HISTOGRAM or GL_MINMAX, or nullptr.
bool* imagingCapability(ImagingState& imaging, GLenum cap);

// The value glPixelTransfer sets for GL_POST_CONVOLUTION_c_SCALE/BIAS and
// GL_POST_COLOR_MATRIX_c_SCALE/BIAS, or nullptr for another pname.
float* imagingTransferParameter(ImagingState& imaging, GLenum pname);

}  // namespace glass::gl
