// glGetString's strings (spec 6.1.11).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

// The string for GL_VENDOR, GL_RENDERER, GL_VERSION or GL_EXTENSIONS; nullptr for other names.
const char* glString(GLenum name);

}  // namespace glass::gl
