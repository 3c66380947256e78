// Selection and feedback (OpenGL 1.5 specification, sections 5.2 and 5.3): what glRenderMode
// switches between, and how primitives, raster positions and pixel commands are recorded
// instead of rasterized.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// glRenderMode's work once the begin/end check passed: validates mode, leaves the current mode
// (returning what it returns: the hit count in GL_SELECT, the number of values written in
// GL_FEEDBACK, -1 when the buffer overflowed, 0 in GL_RENDER) and enters the new one. Records
// GL_INVALID_ENUM / GL_INVALID_OPERATION and changes nothing on error.
GLint setRenderMode(Context& ctx, GLenum mode);

// Selection: a point, line or polygon that survived clipping, or a valid raster position, at
// window depth z (spec 5.2) sets the hit flag and widens the hit's depth range.
void recordHit(Context& ctx, float windowZ);
// Writes the pending hit record, if the hit flag is set, and clears the flag (called before the
// name stack changes and when selection mode ends).
void writeHitRecord(Context& ctx);

// Feedback: appends one value to the feedback buffer (counting values past its end).
void writeFeedbackValue(Context& ctx, float value);
// Appends a vertex as the feedback type asks (table 5.2): x, y [, z] [, w] [, r, g, b, a]
// [, s, t, r, q] in window coordinates, w the clip w.
void writeFeedbackVertex(Context& ctx, const float window[4], const float color[4],
                         const float texCoord[4]);

// glBitmap, glDrawPixels and glCopyPixels outside GL_RENDER mode with a valid raster position:
// in feedback mode the token and the raster position as a vertex (spec 5.3); in selection mode
// nothing (the glRasterPos that set the position already made its hit, as in Mesa).
void recordPixelCommand(Context& ctx, GLenum token);

}  // namespace glass::gl
