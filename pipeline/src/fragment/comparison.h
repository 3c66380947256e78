// The eight comparison functions shared by the alpha, stencil and depth tests (spec 4.1.4-4.1.6):
// the test passes when `incoming func stored` holds.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

inline bool isComparisonFunc(GLenum func) { return func >= GL_NEVER && func <= GL_ALWAYS; }

template <class T>
inline bool passesComparison(GLenum func, T incoming, T stored) {
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return incoming < stored;
    case GL_EQUAL: return incoming == stored;
    case GL_LEQUAL: return incoming <= stored;
    case GL_GREATER: return incoming > stored;
    case GL_NOTEQUAL: return incoming != stored;
    case GL_GEQUAL: return incoming >= stored;
    default: return true;  // GL_ALWAYS
  }
}

}  // namespace glass::gl
