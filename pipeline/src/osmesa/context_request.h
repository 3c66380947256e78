// What OSMesaCreateContextAttribs asks for (include/GL/osmesa.h, Mesa 11.2), read from its
// attribute list and checked against what glass has.
#pragma once

#include <GL/gl.h>

#include <string>

namespace glass::osmesa {

struct ContextRequest {
  GLenum format = GL_RGBA;  // OSMESA_RGBA
  int depthBits = 0, stencilBits = 0, accumBits = 0;
  int majorVersion = 1, minorVersion = 0;
};

// Reads (attribute, value) pairs up to the attribute 0; a NULL list is an empty one. Returns
// false with the reason in `error` for an unknown attribute, a format OSMesa contexts cannot
// have, negative bits, the core profile, or a version newer than glGetString(GL_VERSION)'s.
bool readContextRequest(const int* attributes, ContextRequest& request, std::string& error);

}  // namespace glass::osmesa
