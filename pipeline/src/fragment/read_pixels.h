// glReadPixels (spec 4.3.2): reads a rectangle of the colour, depth or stencil buffer into client
// memory, bottom row first, laid out by the GL_PACK_* parameters of glPixelStore.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// Formats: GL_RGBA, GL_RGB, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE,
// GL_LUMINANCE_ALPHA, GL_BGR, GL_BGRA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX.
// Types: GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT.
bool isReadPixelsFormat(GLenum format);
bool isReadPixelsType(GLenum type);

// Pixels outside the framebuffer are left untouched in client memory. The caller checked the
// errors.
void readPixels(const Context& ctx, int x, int y, int width, int height, GLenum format,
                GLenum type, void* pixels);

}  // namespace glass::gl
