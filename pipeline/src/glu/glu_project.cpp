// gluProject, gluUnProject and gluUnProject4 (GLU 1.3 specification, section 4.3): object coordinates to window
// coordinates through given modelview, projection and viewport, and back. In double precision,
// with the operations in the order of SGI's reference GLU.
#include <GL/glu.h>

#include <cmath>
#include <utility>

namespace {

// out = matrix * in, matrix column-major.
void multiplyMatrixVector(const GLdouble matrix[16], const double in[4], double out[4]) {
  for (int i = 0; i < 4; ++i) {
    out[i] = in[0] * matrix[0 * 4 + i] + in[1] * matrix[1 * 4 + i] + in[2] * matrix[2 * 4 + i] +
             in[3] * matrix[3 * 4 + i];
  }
}

// r = b * a in GL's column-major terms (projection * modelview for a = modelview, b = projection):
// r[i][j] = sum_k a[i][k] b[k][j] on the arrays as stored.
void multiplyMatrices(const GLdouble a[16], const GLdouble b[16], double r[16]) {
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      r[i * 4 + j] = a[i * 4 + 0] * b[0 * 4 + j] + a[i * 4 + 1] * b[1 * 4 + j] +
                     a[i * 4 + 2] * b[2 * 4 + j] + a[i * 4 + 3] * b[3 * 4 + j];
    }
  }
}

// Inverse by Gauss-Jordan elimination with partial pivoting; false when singular.
bool invertMatrix(const double m[16], double inverse[16]) {
  double a[4][8];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[c * 4 + r];
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r) {
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    }
    if (a[pivot][col] == 0.0) return false;
    for (int c = 0; c < 8; ++c) std::swap(a[pivot][c], a[col][c]);
    const double scale = 1.0 / a[col][col];
    for (int c = 0; c < 8; ++c) a[col][c] *= scale;
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double factor = a[r][col];
      for (int c = 0; c < 8; ++c) a[r][c] -= factor * a[col][c];
    }
  }
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) inverse[c * 4 + r] = a[r][c + 4];
  }
  return true;
}

}  // namespace

extern "C" {

GLint gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble* model,
                 const GLdouble* proj, const GLint* view, GLdouble* winX, GLdouble* winY,
                 GLdouble* winZ) {
  if (!model || !proj || !view || !winX || !winY || !winZ) return GLU_FALSE;
  double in[4] = {objX, objY, objZ, 1.0}, out[4];
  multiplyMatrixVector(model, in, out);
  multiplyMatrixVector(proj, out, in);
  if (in[3] == 0.0) return GLU_FALSE;
  for (int i = 0; i < 3; ++i) in[i] /= in[3];
  // [-1, 1] to [0, 1], then x and y to the viewport.
  for (int i = 0; i < 3; ++i) in[i] = in[i] * 0.5 + 0.5;
  *winX = in[0] * view[2] + view[0];
  *winY = in[1] * view[3] + view[1];
  *winZ = in[2];
  return GLU_TRUE;
}

GLint gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble* model,
                   const GLdouble* proj, const GLint* view, GLdouble* objX, GLdouble* objY,
                   GLdouble* objZ) {
  if (!model || !proj || !view || !objX || !objY || !objZ) return GLU_FALSE;
  double combined[16], inverse[16];
  multiplyMatrices(model, proj, combined);
  if (!invertMatrix(combined, inverse)) return GLU_FALSE;
  double in[4] = {winX, winY, winZ, 1.0}, out[4];
  in[0] = (in[0] - view[0]) / view[2];
  in[1] = (in[1] - view[1]) / view[3];
  for (int i = 0; i < 3; ++i) in[i] = in[i] * 2.0 - 1.0;
  multiplyMatrixVector(inverse, in, out);
  if (out[3] == 0.0) return GLU_FALSE;
  *objX = out[0] / out[3];
  *objY = out[1] / out[3];
  *objZ = out[2] / out[3];
  return GLU_TRUE;
}

// GLU 1.3: the same inverse for a point given with its clip w, whose depth range is [near, far];
// the result is not divided by its w, which is returned too.
GLint gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW,
                    const GLdouble* model, const GLdouble* proj, const GLint* view,
                    GLdouble nearVal, GLdouble farVal, GLdouble* objX, GLdouble* objY,
                    GLdouble* objZ, GLdouble* objW) {
  if (!model || !proj || !view || !objX || !objY || !objZ || !objW) return GLU_FALSE;
  double combined[16], inverse[16];
  multiplyMatrices(model, proj, combined);
  if (!invertMatrix(combined, inverse)) return GLU_FALSE;
  double in[4] = {(winX - view[0]) / view[2], (winY - view[1]) / view[3],
                  (winZ - nearVal) / (farVal - nearVal), clipW};
  for (int i = 0; i < 3; ++i) in[i] = in[i] * 2.0 - 1.0;
  double out[4];
  multiplyMatrixVector(inverse, in, out);
  if (out[3] == 0.0) return GLU_FALSE;
  *objX = out[0];
  *objY = out[1];
  *objZ = out[2];
  *objW = out[3];
  return GLU_TRUE;
}

}  // extern "C"
