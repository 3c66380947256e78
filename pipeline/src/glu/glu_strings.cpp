// gluErrorString and gluGetString (GLU 1.3 specification, sections 2.1 and 2.2), with the
// strings of SGI's reference GLU.
#include <GL/glu.h>

extern "C" {

const GLubyte* gluErrorString(GLenum error) {
  const char* text = nullptr;
  switch (error) {
    case GL_NO_ERROR: text = "no error"; break;
    case GL_INVALID_ENUM: case GLU_INVALID_ENUM: text = "invalid enumerant"; break;
    case GL_INVALID_VALUE: case GLU_INVALID_VALUE: text = "invalid value"; break;
    case GL_INVALID_OPERATION: case GLU_INVALID_OPERATION: text = "invalid operation"; break;
    case GL_STACK_OVERFLOW: text = "stack overflow"; break;
    case GL_STACK_UNDERFLOW: text = "stack underflow"; break;
    case GL_OUT_OF_MEMORY: case GLU_OUT_OF_MEMORY: text = "out of memory"; break;
    case GL_TABLE_TOO_LARGE: text = "table too large"; break;
    case GLU_INCOMPATIBLE_GL_VERSION: text = "incompatible gl version"; break;
    default: break;
  }
  return reinterpret_cast<const GLubyte*>(text);
}

const GLubyte* gluGetString(GLenum name) {
  switch (name) {
    case GLU_VERSION: return reinterpret_cast<const GLubyte*>("1.3");
    case GLU_EXTENSIONS: return reinterpret_cast<const GLubyte*>("");
    default: return nullptr;
  }
}

}  // extern "C"
