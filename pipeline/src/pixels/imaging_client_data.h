// Where the imaging commands get their tables and filters from, and how the queries return them
// (OpenGL 1.4 specification, sections 3.6.3 and 6.1.7-6.1.10). Client data is taken as
// glDrawPixels takes it, and the glCopy* commands read the colour buffer as glCopyPixels does,
// both stopping after the conversion to RGBA: no pixel transfer operation applies to a table or
// a filter.
#pragma once

#include <GL/gl.h>

#include <vector>

#include "core/pixel_store.h"

namespace glass::gl {

struct Context;

// The format and type errors of the imaging commands that take or return colour data: those of
// glDrawPixels, and GL_INVALID_ENUM for GL_COLOR_INDEX, GL_STENCIL_INDEX and GL_DEPTH_COMPONENT.
GLenum checkImagingFormatAndType(GLenum format, GLenum type);

// The checks of the queries that return colour data (glGetColorTable, glGetConvolutionFilter,
// glGetSeparableFilter, glGetHistogram, glGetMinmax): GL_INVALID_ENUM for a target the query does
// not take, then those of checkImagingFormatAndType.
GLenum checkImagingQuery(bool targetTaken, GLenum format, GLenum type);

// width x height groups of client data as RGBA floats, row 0 first. Throws std::bad_alloc.
std::vector<float> unpackRgbaBlock(const void* pixels, int width, int height, GLenum format,
                                   GLenum type, const PixelPacking& unpack);

// width x height groups of the colour buffer from (x, y), as RGBA floats in [0, 1]; groups
// outside the framebuffer (undefined by the specification) read as 0. Throws std::bad_alloc.
std::vector<float> readColorBlock(const Context& ctx, int x, int y, int width, int height);

// Writes width x height RGBA groups to client memory in format and type with the pack state
// (luminance is R, as for glGetTexImage, table 6.1).
void packRgbaBlock(const float* rgba, int width, int height, GLenum format, GLenum type,
                   const PixelPacking& pack, void* pixels);

// Whether a command given now reads its client data: not between glBegin and glEnd outside a
// display list, where it will be refused (GL_INVALID_OPERATION) without reading it.
bool readsClientDataNow(const Context& ctx);

// The internal format checks shared by the imaging commands: false (GL_INVALID_ENUM) for a name
// not in table 3.15; histograms and minmax tables take no GL_INTENSITY format.
bool isColorTableFormat(GLenum internalFormat);
bool isHistogramFormat(GLenum internalFormat);

}  // namespace glass::gl
