// The matrices of glTranslate, glScale, glRotate, glOrtho and glFrustum (OpenGL 1.5 spec,
// section 2.11.2). The GL entry points multiply the current matrix by these.
#pragma once

#include "core/matrix.h"

namespace glass::gl {

Matrix4 translationMatrix(float x, float y, float z);
Matrix4 scaleMatrix(float x, float y, float z);

// Rotation by angleDegrees counter-clockwise about the axis (x, y, z), which is normalized first.
// Returns false for a zero axis, or one shorter than 1e-4 (GL leaves the result undefined; glass
// then leaves the matrix unchanged, as Mesa does). Rounded as Mesa rounds (see the source).
bool rotationMatrix(float angleDegrees, float x, float y, float z, Matrix4& rotation);

// Computed in float from the arguments rounded to float, as Mesa computes them. The caller
// checks the spec's error conditions.
Matrix4 orthoMatrix(double left, double right, double bottom, double top, double zNear, double zFar);
Matrix4 frustumMatrix(double left, double right, double bottom, double top, double zNear,
                      double zFar);

}  // namespace glass::gl
