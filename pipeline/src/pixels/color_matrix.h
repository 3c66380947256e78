// The colour matrix transformation (OpenGL 1.4 specification, section 3.6.5, "Color Matrix
// Transformation"): each RGBA group, taken as a column vector, is multiplied by the top of the
// colour matrix stack (glMatrixMode(GL_COLOR)), then each component is multiplied by its
// GL_POST_COLOR_MATRIX_c_SCALE and GL_POST_COLOR_MATRIX_c_BIAS is added.
#pragma once

#include "core/matrix.h"

namespace glass::gl {

// Whether the stage leaves every group as it is (identity matrix, scale 1, bias 0).
bool colorMatrixIsIdentity(const Matrix4& m, const float scale[4], const float bias[4]);

// count RGBA groups, in place. Sums are formed in float in the order R, G, B, A.
void transformByColorMatrix(const Matrix4& m, const float scale[4], const float bias[4],
                            float* rgba, int count);

}  // namespace glass::gl
