// glLoadTransposeMatrix and glMultTransposeMatrix (OpenGL 1.3, spec 2.10.2): the matrix given
// row by row. By definition LoadTransposeMatrix[fd](m) is LoadMatrix[fd](m^T) and likewise for
// Mult, so they are compiled into display lists as the commands they stand for.
#include <GL/gl.h>

namespace {

template <class T>
void transpose(const T* m, T* t) {
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) t[column * 4 + row] = m[row * 4 + column];
  }
}

}  // namespace

extern "C" {

void glLoadTransposeMatrixf(const GLfloat* m) {
  if (!m) return;
  GLfloat t[16];
  transpose(m, t);
  glLoadMatrixf(t);
}

void glLoadTransposeMatrixd(const GLdouble* m) {
  if (!m) return;
  GLdouble t[16];
  transpose(m, t);
  glLoadMatrixd(t);
}

void glMultTransposeMatrixf(const GLfloat* m) {
  if (!m) return;
  GLfloat t[16];
  transpose(m, t);
  glMultMatrixf(t);
}

void glMultTransposeMatrixd(const GLdouble* m) {
  if (!m) return;
  GLdouble t[16];
  transpose(m, t);
  glMultMatrixd(t);
}

}  // extern "C"
