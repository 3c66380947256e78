// glReadPixels (spec 4.3.2): reads a rectangle of the colour, depth or stencil buffer into client
// memory, bottom row first, through the pixel transfer operations (pixels/pixel_transfer.h) and
// laid out by the GL_PACK_* parameters of glPixelStore (texture/client_pixels.h packs).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// The format and type errors of glReadPixels: those of checkPixelFormatAndType (every format
// and type of tables 3.5 and 3.6, packed types with matching formats), and GL_INVALID_OPERATION
// for GL_COLOR_INDEX, which an RGBA context cannot read.
GLenum checkReadPixelsFormatAndType(GLenum format, GLenum type);

// Pixels outside the framebuffer are left untouched in client memory (with the imaging
// operations, pixels/imaging_pipeline.h, they are read as 0 and written). The caller checked the
// errors.
void readPixels(Context& ctx, int x, int y, int width, int height, GLenum format,
                GLenum type, void* pixels);

}  // namespace glass::gl
